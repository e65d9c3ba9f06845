// The pages an import keeps for reuse (obj_spare_mappings.hpp, keep_for_reuse in obj_buffer.hpp):
// a kept array's mapping comes back, with what was written in it, for a later array that fits —
// a small array takes a piece of it, leaving the rest kept; never for one that does not; and
// release gives everything back.
#include <catch2/catch.hpp>

#include <cstdint>

#include "obj_buffer.hpp"
#include "obj_spare_mappings.hpp"

using pfx_obj::BigVector;

namespace {
constexpr size_t kBig = (size_t{8} << 20) / sizeof(uint32_t);  // above the allocator's mapping threshold
}

TEST_CASE("obj spare mappings: a kept array's written pages serve the next array that fits", "[objimport][memory]") {
  pfx_obj::release_spare_mappings();
  BigVector<uint32_t> corners;
  corners.reserve(2 * kBig);  // reserved like a chunk's corners: more than is written
  corners.resize(kBig / 2);
  for (size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<uint32_t>(i * 7);
  const uint32_t* pages = corners.data();
  pfx_obj::keep_for_reuse(&corners);
  CHECK(corners.empty());
  CHECK(corners.capacity() == 0);

  BigVector<float> too_large;
  too_large.resize(3 * kBig);  // 24 MB: larger than the kept 16 MB reservation, so fresh pages
  CHECK(static_cast<const void*>(too_large.data()) != static_cast<const void*>(pages));

  BigVector<uint32_t> positions;
  positions.resize(kBig);  // fits: gets the kept mapping, trimmed, with its contents
  REQUIRE(static_cast<const void*>(positions.data()) == static_cast<const void*>(pages));
  CHECK(positions[0] == 0);
  CHECK(positions[kBig / 2 - 1] == static_cast<uint32_t>((kBig / 2 - 1) * 7));
  positions[kBig - 1] = 5;  // the trimmed mapping still covers the whole array
  CHECK(positions[kBig - 1] == 5);

  BigVector<uint32_t> another;
  another.resize(kBig);  // the only kept mapping is taken: a fresh one
  CHECK(another.data() != positions.data());
  pfx_obj::release_spare_mappings();
}

TEST_CASE("obj spare mappings: release unmaps what is kept, later arrays are fresh", "[objimport][memory]") {
  pfx_obj::release_spare_mappings();
  BigVector<uint32_t> a;
  a.resize(kBig);
  a[0] = 42;
  pfx_obj::keep_for_reuse(&a);
  pfx_obj::release_spare_mappings();
  BigVector<uint32_t> b;
  b.resize(kBig);
  b[0] = 1;  // writable, whatever address it got
  CHECK(b[0] == 1);
  CHECK(pfx_obj::take_spare_mapping(1) == nullptr);  // nothing kept
}

TEST_CASE("obj spare mappings: small arrays are freed at once, not kept", "[objimport][memory]") {
  pfx_obj::release_spare_mappings();
  BigVector<uint32_t> small;
  small.resize(16);
  pfx_obj::keep_for_reuse(&small);
  CHECK(pfx_obj::take_spare_mapping(1) == nullptr);
}

TEST_CASE("obj spare mappings: a small array takes a piece of a kept mapping, the rest stays kept", "[objimport][memory]") {
  pfx_obj::release_spare_mappings();
  BigVector<uint32_t> corners;
  corners.reserve(2 * kBig);
  corners.resize(kBig / 2);  // 4 MB written of a 16 MB mapping
  for (size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<uint32_t>(i * 7);
  const uint32_t* pages = corners.data();
  pfx_obj::keep_for_reuse(&corners);

  constexpr size_t kSmall = (size_t{64} << 10) / sizeof(uint32_t);  // the allocator's mapping threshold
  BigVector<uint32_t> small;
  small.resize(kSmall);  // the first 64 KB of the kept mapping
  REQUIRE(static_cast<const void*>(small.data()) == static_cast<const void*>(pages));
  CHECK(small[kSmall - 1] == static_cast<uint32_t>((kSmall - 1) * 7));

  BigVector<uint32_t> next;
  next.resize(kBig);  // the rest, with its written pages, serves the next array that fits
  REQUIRE(static_cast<const void*>(next.data()) == static_cast<const void*>(pages + kSmall));
  CHECK(next[0] == static_cast<uint32_t>(kSmall * 7));
  CHECK(next[kBig / 2 - kSmall - 1] == static_cast<uint32_t>((kBig / 2 - 1) * 7));
  next[kBig - 1] = 9;  // mapped to its end
  CHECK(next[kBig - 1] == 9);

  pfx_obj::release_spare_mappings();
}
