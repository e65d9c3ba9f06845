// Freeing a large result on several threads (obj_parallel_free.hpp): the pages wholly inside the
// given ranges are dropped, those only partly inside (which may hold another array's bytes) and
// everything outside are not; no pool, one thread, or too few bytes, drops nothing (the munmap
// after it frees them). Checked by reading the memory back: a dropped page of a private anonymous mapping
// reads as zeros.
#include <catch2/catch.hpp>

#include <sys/mman.h>
#include <unistd.h>

#include <cstring>

#include "obj_parallel_free.hpp"
#include "obj_test_support.hpp"

using pfx_obj::ByteRange;

namespace {

// A mapping filled with 0xAB, unmapped when the test ends.
struct Filled {
  explicit Filled(size_t bytes) : bytes(bytes) {
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    REQUIRE(p != MAP_FAILED);
    data = static_cast<unsigned char*>(p);
    std::memset(data, 0xAB, bytes);
  }
  ~Filled() { ::munmap(data, bytes); }
  bool all(size_t from, size_t to, unsigned char value) const {
    for (size_t i = from; i < to; ++i)
      if (data[i] != value) return false;
    return true;
  }
  size_t bytes;
  unsigned char* data = nullptr;
};

const size_t kPage = static_cast<size_t>(::sysconf(_SC_PAGESIZE));

}  // namespace

TEST_CASE("obj parallel free: two threads drop the whole pages inside the ranges, nothing else", "[objimport][memory]") {
  const size_t size = pfx_obj::kMinParallelFreeBytes + 16 * kPage;
  Filled a(size), b(64 * kPage);
  // a: from 100 bytes in to 100 bytes before the end, so its first and last pages are partly
  // outside; b: a small range of whole pages (the total decides, not each range).
  const std::vector<ByteRange> ranges = {{a.data + 100, size - 200}, {b.data + 8 * kPage, 4 * kPage}};
  pfx_obj::drop_pages_in_parallel(pfx_obj_test::test_pool(2), 2, ranges);
  CHECK(a.all(0, kPage, 0xAB));                 // partly outside: kept
  CHECK(a.all(kPage, size - kPage, 0));         // whole pages inside: dropped
  CHECK(a.all(size - kPage, size, 0xAB));       // partly outside: kept
  CHECK(b.all(0, 8 * kPage, 0xAB));             // before the range
  CHECK(b.all(8 * kPage, 12 * kPage, 0));
  CHECK(b.all(12 * kPage, 64 * kPage, 0xAB));   // after it
}

TEST_CASE("obj parallel free: no pool, one thread, or less than the minimum in all, drops nothing", "[objimport][memory]") {
  const size_t size = pfx_obj::kMinParallelFreeBytes + 16 * kPage;
  Filled a(size);
  pfx_obj::drop_pages_in_parallel(nullptr, 2, {{a.data, size}});
  CHECK(a.all(0, size, 0xAB));
  pfx_obj::drop_pages_in_parallel(pfx_obj_test::test_pool(2), 1, {{a.data, size}});
  CHECK(a.all(0, size, 0xAB));
  pfx_obj::drop_pages_in_parallel(pfx_obj_test::test_pool(2), 2, {{a.data, pfx_obj::kMinParallelFreeBytes - kPage}});
  CHECK(a.all(0, size, 0xAB));
  pfx_obj::drop_pages_in_parallel(pfx_obj_test::test_pool(2), 2, {{a.data + 1, kPage - 1}, {a.data + 10, 0}});  // no whole page at all
  CHECK(a.all(0, size, 0xAB));
}
