// round_to_half against OpenEXR's Imath::half, the reference every EXR file pfx writes goes
// through: the same float back for the values at every edge of the half range and for a sample
// of 2^24 bit patterns spread over all floats.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include <Imath/half.h>

#include "half_rounding.hpp"

namespace {

float from_bits(uint32_t bits) {
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// Bit for bit, NaN for NaN (a NaN's payload is not kept by either).
bool same(float got, float want) {
  if (std::isnan(want)) return std::isnan(got);
  return std::memcmp(&got, &want, sizeof got) == 0;
}

}  // namespace

TEST_CASE("round_to_half gives Imath::half's value at the edges of the half range") {
  const float inf = std::numeric_limits<float>::infinity();
  for (float value : {0.0f, -0.0f, 1.0f, -1.0f, 0.1f, 1.0f / 3.0f, 65504.0f, 65519.99f, 65520.0f, -65520.0f, 65536.0f,
                      1e10f, -1e10f, inf, -inf, std::nanf(""), 6.103515625e-05f /* 2^-14 */, 6.1e-05f,
                      5.9604645e-08f /* 2^-24 */, 2.98e-08f, 2.9802322e-08f /* 2^-25: a tie, to zero */,
                      8.940697e-08f /* 1.5 * 2^-24: a tie, to 2^-23 */, 1e-30f, from_bits(1u), from_bits(0x7f7fffffu),
                      1.00048828125f /* a tie between 1 and 1 + 2^-10: to 1 */, 1.00146484375f /* to 1 + 2^-9 */})
    CHECK(same(pfx::app::round_to_half(value), static_cast<float>(Imath::half(value))));
}

TEST_CASE("round_to_half gives Imath::half's value over 2^24 floats of every sign and exponent") {
  std::mt19937 random(20261128);
  size_t differing = 0;
  for (int i = 0; i < (1 << 24); ++i) {
    const float value = from_bits(static_cast<uint32_t>(random()));
    differing += !same(pfx::app::round_to_half(value), static_cast<float>(Imath::half(value)));
  }
  CHECK(differing == 0);
}
