// The importer's large working arrays: std::vector with an allocator that (1) maps big buffers
// directly, so an array reserved for the most a chunk could hold costs address space only — the
// pages never written are never touched — and unmaps them as a whole when freed, and (2) leaves
// elements uninitialised on resize(): every element is written before it is read, and zero-filling
// first only doubled the memory traffic.
//
// No transparent huge pages: a huge page is a free 2 MB block, and on virtual machines whose guest
// hands free memory back to the host (virtio-balloon free page reporting, as on the machines this
// project is measured on) such a block has usually been handed back, so touching it makes the host
// fault it in again. Measured there: touching 400 MB took 0.02 s with huge pages just freed by the
// previous process, 1.0-1.3 s with huge pages after 3 s idle, and 0.15-0.20 s with 4 KB pages in
// either case; pfx-import on a 99 MB file after 3 s idle took 310 ms with huge pages, 140 ms
// without (docs/importers/obj.md).
#pragma once

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <new>
#include <utility>
#include <vector>

#include "obj_spare_mappings.hpp"

namespace pfx_obj {

template <typename T>
struct BigBufferAllocator {
  using value_type = T;
  // Below this, the ordinary heap: mapping small buffers costs more than it saves. From here up,
  // an array can take pages kept for reuse (obj_spare_mappings.hpp) — with 4 MB here, the vertex
  // arrays of a 10 MB file (0.4-0.6 MB each) were always fresh pages, and filling them took
  // 1.3-1.6 ms of a 10 ms import on one thread instead of 0.7 ms.
  static constexpr size_t kMapThreshold = size_t{64} << 10;

  BigBufferAllocator() = default;
  template <typename U>
  BigBufferAllocator(const BigBufferAllocator<U>&) {}

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kMapThreshold) return static_cast<T*>(::operator new(bytes));
    if (void* spare = take_spare_mapping(bytes)) return static_cast<T*>(spare);
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return static_cast<T*>(p);
  }

  void deallocate(T* p, size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kMapThreshold) ::operator delete(p);
    else if (keep_written_ != kNotKept) keep_spare_mapping(p, bytes, keep_written_);
    else ::munmap(p, bytes);
  }

  // Set by keep_for_reuse around the one deallocation it makes.
  static constexpr size_t kNotKept = ~size_t{0};
  static inline thread_local size_t keep_written_ = kNotKept;

  // Default-initialisation: nothing at all for the plain numbers and structs stored here.
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <typename U>
  bool operator==(const BigBufferAllocator<U>&) const { return true; }
  template <typename U>
  bool operator!=(const BigBufferAllocator<U>&) const { return false; }
};

template <typename T>
using BigVector = std::vector<T, BigBufferAllocator<T>>;

// Frees the array, keeping its mapping (with its written pages) for the import's next arrays
// (obj_spare_mappings.hpp) instead of unmapping it.
template <typename T>
void keep_for_reuse(BigVector<T>* array) {
  BigVector<T> freed;
  freed.swap(*array);
  BigBufferAllocator<T>::keep_written_ = freed.size() * sizeof(T);
  freed = BigVector<T>();  // the one deallocation, of the kept array
  BigBufferAllocator<T>::keep_written_ = BigBufferAllocator<T>::kNotKept;
}

// Empties an array and gives its memory back at once. `array = {}` does not: it calls
// operator=(initializer_list), which destroys the elements and keeps the capacity, so the memory
// went back only with the array's owner (a 487 MB file's 35 MB of vertex keys, say, at the very
// end of the import instead of after the normals).
template <typename Array>
void free_array(Array* array) {
  Array().swap(*array);
}

// Element-wise equality with a plain vector (tests compare results with literals).
template <typename T>
bool operator==(const BigVector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}
template <typename T>
bool operator==(const std::vector<T>& a, const BigVector<T>& b) {
  return b == a;
}

}  // namespace pfx_obj
