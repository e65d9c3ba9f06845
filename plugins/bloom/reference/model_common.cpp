#include "model_common.hpp"

#include <algorithm>
#include <cmath>

namespace pfx_bloom::model {

double largest(const Plane& p) {
  double m = 0;
  for (double v : p.rgb) m = std::max(m, v);
  return m;
}

void texel(const Plane& p, int x, int y, Wrap wrap, double out[3]) {
  if (wrap == Wrap::Border && (x < 0 || y < 0 || x >= p.w || y >= p.h)) {
    out[0] = out[1] = out[2] = 0.0;
    return;
  }
  const double* t = p.at(std::clamp(x, 0, p.w - 1), std::clamp(y, 0, p.h - 1));
  out[0] = t[0], out[1] = t[1], out[2] = t[2];
}

void bilinear(const Plane& p, double px, double py, Wrap wrap, double out[3]) {
  const double u = px - 0.5, v = py - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const double a = u - fu, b = v - fv;
  const int i = static_cast<int>(fu), j = static_cast<int>(fv);
  double t00[3], t10[3], t01[3], t11[3];
  texel(p, i, j, wrap, t00);
  texel(p, i + 1, j, wrap, t10);
  texel(p, i, j + 1, wrap, t01);
  texel(p, i + 1, j + 1, wrap, t11);
  for (int c = 0; c < 3; ++c)
    out[c] = (1 - b) * ((1 - a) * t00[c] + a * t10[c]) + b * ((1 - a) * t01[c] + a * t11[c]);
}

bool not_finite(float v) { return !std::isfinite(v); }

Plane safe_frame(const float* color, int w, int h, double clamp_to, int nonfinite) {
  Plane p(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* v = color + (static_cast<size_t>(y) * w + x) * 4;
      if (nonfinite == NONFINITE_ZERO && (not_finite(v[0]) || not_finite(v[1]) || not_finite(v[2]))) continue;
      for (int c = 0; c < 3; ++c) p.at(x, y)[c] = std::isnan(v[c]) ? 0.0 : std::clamp(static_cast<double>(v[c]), 0.0, clamp_to);
    }
  return p;
}

double soft_part(const Settings& s, double b) {
  double part = std::max(b - s.threshold, 0.0);
  if (s.knee > 0) {
    const double soft = std::clamp(b - s.threshold + s.knee, 0.0, 2.0 * s.knee);
    part = std::max(part, soft * soft / (4.0 * s.knee));
  }
  return part;
}

void bright_part(const Settings& s, int measure, double c[3]) {
  if (measure == kMeasurePerChannel) {
    for (int i = 0; i < 3; ++i) c[i] = soft_part(s, c[i]);
    return;
  }
  const double b = measure == MEASURE_LUMINANCE ? 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
                                                : std::max(c[0], std::max(c[1], c[2]));
  const double ratio = soft_part(s, b) / std::max(b, kBrightnessFloor);
  for (int i = 0; i < 3; ++i) c[i] *= ratio;
}

double karis_weight(const double c[3]) { return 1.0 / (1.0 + 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]); }

Plane box_bright(const Settings& s, int measure, const Plane& frame, int w, int h, int block, int pad_x, int pad_y,
                 const double gain[3], double cap, bool karis) {
  Plane out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int x0 = x * block - pad_x, y0 = y * block - pad_y;
      double sum[3] = {0, 0, 0}, weights = 0;
      for (int j = 0; j < block; ++j)
        for (int i = 0; i < block; ++i) {
          double t[3];
          texel(frame, x0 + i, y0 + j, Wrap::Border, t);
          bright_part(s, measure, t);
          const double weight = karis ? karis_weight(t) : 1.0;
          for (int c = 0; c < 3; ++c) sum[c] += weight * t[c];
          weights += weight;
        }
      for (int c = 0; c < 3; ++c) out.at(x, y)[c] = std::min(sum[c] / weights * gain[c], cap);
    }
  return out;
}

double finite_signed(float v) { return std::isnan(v) ? 0.0 : std::clamp(static_cast<double>(v), -kHalfMax, kHalfMax); }

void finite_pixel(const float* rgba, int nonfinite, double out[4]) {
  for (int c = 0; c < 4; ++c) out[c] = finite_signed(rgba[c]);
  if (nonfinite != NONFINITE_ZERO) return;
  if (not_finite(rgba[0]) || not_finite(rgba[1]) || not_finite(rgba[2])) out[0] = out[1] = out[2] = 0.0;
  if (not_finite(rgba[3])) out[3] = 0.0;
}

}  // namespace pfx_bloom::model
