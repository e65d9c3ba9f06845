#include "obj_parallel_free.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>

#include "obj_parallel.hpp"

namespace pfx_obj {

namespace {

// The array's elements where it is a mapping of its own (obj_buffer.hpp; small ones are heap).
// Not its whole capacity: the index array is often the vertex numbers' reservation, 611 MB of
// address space for 53 MB written at 487 MB, and split by capacity its written pages would fall
// in one thread's piece. What lies beyond is freed by the munmap after.
template <typename T>
void add_mapped(const BigVector<T>& array, std::vector<ByteRange>* ranges) {
  if (array.capacity() * sizeof(T) >= BigBufferAllocator<T>::kMapThreshold)
    ranges->push_back(ByteRange{array.data(), array.size() * sizeof(T)});
}

}  // namespace

void drop_pages_in_parallel(const pfx_thread_pool* pool, unsigned threads, const std::vector<ByteRange>& ranges) {
  if (!pool || threads < 2) return;
  std::vector<ByteRange> whole;  // each range's whole pages
  size_t total = 0;
  for (const ByteRange& range : ranges) {
    const ByteRange pages = whole_pages_inside(range.begin, range.bytes);
    if (pages.bytes == 0) continue;
    whole.push_back(pages);
    total += pages.bytes;
  }
  if (total < kMinParallelFreeBytes) return;
  const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));  // whole_pages_inside found it valid
  // A few pieces per thread, so that the threads finish together; not many more — each call
  // flushes the other threads' TLBs.
  const size_t piece = std::max<size_t>(size_t{1} << 20, total / (size_t{threads} * 4)) / page * page;
  std::vector<ByteRange> pieces;
  for (const ByteRange& range : whole)
    for (size_t at = 0; at < range.bytes; at += piece)
      pieces.push_back(ByteRange{static_cast<const char*>(range.begin) + at, std::min(piece, range.bytes - at)});
  run_parallel(pool, threads, pieces.size(), [&](size_t i, unsigned) {
    // Best effort: where it fails, the munmap that follows frees the pages all the same.
    ::madvise(const_cast<void*>(pieces[i].begin), pieces[i].bytes, MADV_DONTNEED);
  });
}

void free_mesh_in_parallel(const pfx_thread_pool* pool, unsigned threads, ObjMesh* mesh) {
  std::vector<ByteRange> ranges;
  add_mapped(mesh->positions, &ranges);
  add_mapped(mesh->normals, &ranges);
  add_mapped(mesh->texcoords, &ranges);
  add_mapped(mesh->colors, &ranges);
  add_mapped(mesh->indices, &ranges);
  drop_pages_in_parallel(pool, threads, ranges);
  free_array(&mesh->positions);
  free_array(&mesh->normals);
  free_array(&mesh->texcoords);
  free_array(&mesh->colors);
  free_array(&mesh->indices);
}

}  // namespace pfx_obj
