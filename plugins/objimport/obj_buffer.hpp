// The importer's large working arrays: std::vector with an allocator that (1) maps big buffers
// directly, so an array reserved for the most a chunk could hold costs address space only — the
// pages never written are never touched — and unmaps them as a whole when freed, and (2) leaves
// elements uninitialised on resize(): every element is written before it is read, and zero-filling
// first only doubled the memory traffic.

#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace pfx_obj {

template <typename T>
struct BigBufferAllocator {
  using value_type = T;
  // Below this, the ordinary heap: mapping small buffers costs more than it saves.
  static constexpr size_t kMapThreshold = size_t{64} << 10;

  BigBufferAllocator() = default;
  template <typename U>
  BigBufferAllocator(const BigBufferAllocator<U>&) {}

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kMapThreshold) return static_cast<T*>(::operator new(bytes));
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return static_cast<T*>(p);
  }

  void deallocate(T* p, size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kMapThreshold) ::operator delete(p);
    else ::munmap(p, bytes);
  }

  // Default-initialisation: nothing at all for the plain numbers and structs stored here.
  template <typename U>
  void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) { ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...); }

  template <typename U>
  bool operator==(const BigBufferAllocator<U>&) const { return true; }
  template <typename U>
  bool operator!=(const BigBufferAllocator<U>&) const { return false; }
};

template <typename T>
using BigVector = std::vector<T, BigBufferAllocator<T>>;

// Empties an array and gives its memory back now (`array = {}` keeps the capacity).
template <typename Array>
void free_array(Array* array) {
  Array().swap(*array);
}
}  // namespace pfx_obj
