// Rounding a value to what an RGBA16F / R16F texel stores (IEEE binary16, round to nearest even),
// so the CPU models see the same stored intermediates as the GPU passes.
#pragma once

#include <cmath>

namespace pfx_dof {

// NaN stays NaN; magnitudes from 65520 up become infinities, as a GPU's conversion does;
// values below the smallest normal half keep a fixed absolute step of 2^-24 (denormals).
inline double to_half(double v) {
  if (!std::isfinite(v)) return v;
  const double a = std::fabs(v);
  if (a >= 65520.0) return std::copysign(HUGE_VAL, v);
  int exponent = 0;
  std::frexp(a, &exponent);  // a = m * 2^exponent, m in [0.5, 1)
  // 11 significant bits for normals (exponent >= -13), a fixed 2^-24 step below.
  const int step_exponent = exponent >= -13 ? exponent - 11 : -24;
  const double step = std::ldexp(1.0, step_exponent);
  return std::copysign(std::nearbyint(a / step) * step, v);  // nearbyint: ties to even
}

}  // namespace pfx_dof
