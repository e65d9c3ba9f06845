// The whole pages inside a range of memory: what madvise may drop without touching bytes of the
// neighbouring memory that share the range's first and last pages.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>

namespace pfx_obj {

struct ByteRange {
  const void* begin;
  size_t bytes;
};

// The whole pages inside [begin, begin + bytes): page-aligned, bytes 0 when there is none.
inline ByteRange whole_pages_inside(const void* begin, size_t bytes) {
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (page_size <= 0) return ByteRange{begin, 0};
  const uintptr_t page = static_cast<uintptr_t>(page_size), at = reinterpret_cast<uintptr_t>(begin);
  const uintptr_t first = (at + page - 1) / page * page, end = (at + bytes) / page * page;
  return ByteRange{reinterpret_cast<const void*>(first), end > first ? end - first : 0};
}

}  // namespace pfx_obj
