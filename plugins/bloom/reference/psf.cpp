#include "reference/psf.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bloom_levels.hpp"

namespace pfx_bloom::psf {
namespace {

using fft::Kernel;

Kernel zeros(int w, int h, int cx, int cy) {
  Kernel k;
  k.w = w, k.h = h, k.cx = cx, k.cy = cy;
  k.taps.assign(static_cast<size_t>(w) * h, 0.0);
  return k;
}

// The 1-D Gaussian integrated over each pixel, out to 6 sigma (the rest is below 1e-9), at most
// `limit` taps from the centre.
std::vector<double> gaussian_1d(double sigma, int limit, int* radius) {
  *radius = std::min(static_cast<int>(std::ceil(6.0 * sigma)) + 1, limit);
  std::vector<double> w(static_cast<size_t>(2 * *radius + 1));
  const double scale = 1.0 / (sigma * std::sqrt(2.0));
  for (int k = -*radius; k <= *radius; ++k)
    w[static_cast<size_t>(k + *radius)] = 0.5 * (std::erf((k + 0.5) * scale) - std::erf((k - 0.5) * scale));
  return w;
}

void add_gaussian(Kernel& k, double sigma, double weight) {
  int rx, ry;
  const std::vector<double> gx = gaussian_1d(sigma, k.cx, &rx), gy = gaussian_1d(sigma, k.cy, &ry);
  for (int y = -ry; y <= ry; ++y)
    for (int x = -rx; x <= rx; ++x)
      k.at(k.cx + x, k.cy + y) += weight * gx[static_cast<size_t>(x + rx)] * gy[static_cast<size_t>(y + ry)];
}

// A bilinear tap off the centre of an output texel, whose source position is 2n + 1 (texel edges):
// its weights on the source texels 2n + m, as a kernel in m.
struct Tap {
  double dx, dy, weight;
};

Kernel from_taps(const std::vector<Tap>& taps) {
  Kernel k = zeros(12, 12, 6, 6);  // offsets -6 .. 5 hold every stage here
  for (const Tap& t : taps) {
    const double u = 0.5 + t.dx, v = 0.5 + t.dy;
    const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
    const double fu = u - i, fv = v - j;
    k.at(k.cx + i, k.cy + j) += t.weight * (1 - fu) * (1 - fv);
    k.at(k.cx + i + 1, k.cy + j) += t.weight * fu * (1 - fv);
    k.at(k.cx + i, k.cy + j + 1) += t.weight * (1 - fu) * fv;
    k.at(k.cx + i + 1, k.cy + j + 1) += t.weight * fu * fv;
  }
  return k;
}

// The pyramid's bright pass: the centre weighted 4/8, the four diagonal neighbours 1/8.
std::vector<Tap> bright5() { return {{0, 0, 0.5}, {-1, -1, 0.125}, {1, -1, 0.125}, {-1, 1, 0.125}, {1, 1, 0.125}}; }

// The pyramid's downsample: 4 x 4 taps at +-0.92, +-2.75 weighted 0.3913, 0.1087 per axis.
std::vector<Tap> down16() {
  const double o[4] = {-2.75, -0.92, 0.92, 2.75}, w[4] = {0.1087, 0.3913, 0.3913, 0.1087};
  std::vector<Tap> taps;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) taps.push_back({o[i], o[j], w[i] * w[j]});
  return taps;
}

// Jimenez's 13 taps: five 4x4 boxes of four taps, the centre box (taps at +-1) 0.5, the corner
// boxes (taps at 0 and +-2, on one side each) 0.125 each, each tap a quarter of its box.
std::vector<Tap> down13() {
  std::vector<Tap> taps;
  for (int sy : {-1, 1})
    for (int sx : {-1, 1}) taps.push_back({double(sx), double(sy), 0.5 / 4});
  for (int by : {-2, 0})
    for (int bx : {-2, 0})
      for (int ty : {0, 2})
        for (int tx : {0, 2}) taps.push_back({double(bx + tx), double(by + ty), 0.125 / 4});
  return taps;
}

// The tent from level i+1 into level i as an interpolation filter: level-(i+1) texel n feeds
// level-i pixel t with weight g(t - 2n). Four taps half a texel off the pixel's centre, a quarter each.
Kernel tent() {
  Kernel g = zeros(8, 8, 4, 4);
  double g1[8] = {};  // per axis: offsets -4 .. 3
  for (int p = 0; p < 2; ++p)
    for (double side : {-0.5, 0.5}) {
      const double u = (p + 0.5) / 2.0 + side - 0.5;  // in texels of the coarse level, from n
      const int q = static_cast<int>(std::floor(u));
      const double f = u - q;
      g1[p - 2 * q + 4] += 0.5 * (1 - f);
      g1[p - 2 * (q + 1) + 4] += 0.5 * f;
    }
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) g.at(x, y) = g1[x] * g1[y];
  return g;
}

// k with its offsets multiplied by `factor` (zeros in between).
Kernel upsampled(const Kernel& k, int factor) {
  Kernel u = zeros((k.w - 1) * factor + 1, (k.h - 1) * factor + 1, k.cx * factor, k.cy * factor);
  for (int y = 0; y < k.h; ++y)
    for (int x = 0; x < k.w; ++x) u.at(x * factor, y * factor) = k.at(x, y);
  return u;
}

Kernel trimmed(const Kernel& k) {  // without all-zero borders
  int x0 = k.w, x1 = -1, y0 = k.h, y1 = -1;
  for (int y = 0; y < k.h; ++y)
    for (int x = 0; x < k.w; ++x)
      if (k.at(x, y) != 0.0) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (x1 < 0) return zeros(1, 1, 0, 0);
  Kernel t = zeros(x1 - x0 + 1, y1 - y0 + 1, k.cx - x0, k.cy - y0);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) t.at(x - x0, y - y0) = k.at(x, y);
  return t;
}

Kernel add_into(Kernel sum, const Kernel& k, double weight) {
  // Grow sum to hold k (both centred), then add.
  const int left = std::max(sum.cx, k.cx), right = std::max(sum.w - sum.cx, k.w - k.cx);
  const int down = std::max(sum.cy, k.cy), up = std::max(sum.h - sum.cy, k.h - k.cy);
  Kernel out = zeros(left + right, down + up, left, down);
  for (int y = 0; y < sum.h; ++y)
    for (int x = 0; x < sum.w; ++x) out.at(x - sum.cx + left, y - sum.cy + down) += sum.at(x, y);
  for (int y = 0; y < k.h; ++y)
    for (int x = 0; x < k.w; ++x) out.at(x - k.cx + left, y - k.cy + down) += weight * k.at(x, y);
  return out;
}

}  // namespace

Kernel gaussian(double sigma, int frame_w, int frame_h) {
  Kernel k = zeros(2 * frame_w - 1, 2 * frame_h - 1, frame_w - 1, frame_h - 1);
  add_gaussian(k, sigma, 1.0);
  return trimmed(k);
}

Kernel chain_level(int mode, int level) {
  const bool thirteen = mode == MODE_CHAIN13;
  const Kernel first = trimmed(from_taps(thirteen ? down13() : bright5()));
  const Kernel down = trimmed(from_taps(thirteen ? down13() : down16()));
  const Kernel g = trimmed(tent());
  Kernel f = first, up = g;
  for (int i = 1; i <= level; ++i) {
    f = fft::convolve_kernels(f, upsampled(down, 1 << i));
    up = fft::convolve_kernels(up, upsampled(g, 1 << i));
  }
  Kernel k = fft::convolve_kernels(fft::reversed(f), up);
  const double m = std::ldexp(1.0, level + 1);
  for (double& v : k.taps) v /= m * m;
  return trimmed(k);
}

Kernel of_mode(const Settings& s, int levels, int frame_w, int frame_h) {
  Kernel sum = zeros(1, 1, 0, 0);
  if (s.mode == MODE_GAUSSIAN) return gaussian(s.sigma, frame_w, frame_h);
  if (s.mode == MODE_MGF) {
    double weights[kMaxLevels], variance = 0;
    level_weights(s, levels, weights);
    Kernel k = zeros(2 * frame_w - 1, 2 * frame_h - 1, frame_w - 1, frame_h - 1);
    for (int i = 0; i < levels; ++i) {
      const double own = kMgfDeviation * 4.0 * std::ldexp(1.0, i);
      variance += own * own;
      add_gaussian(k, std::sqrt(variance), weights[i]);
    }
    return trimmed(k);
  }
  for (int i = 0; i < levels; ++i) sum = add_into(sum, chain_level(s.mode, i), 1.0 / levels);
  return sum;
}

}  // namespace pfx_bloom::psf
