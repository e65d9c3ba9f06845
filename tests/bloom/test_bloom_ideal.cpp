// PFX_REFERENCE_IDEAL of bloom: the FFT convolution against a direct sum, each mode's point spread
// function against what it must be (the chain's against the phase average of its own model's point
// responses, the Gaussians' against their moments), and the ideal against the model where the mode
// is exact.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "bloom_params.hpp"
#include "reference/bloom_model.hpp"
#include "reference/fft_convolution.hpp"
#include "reference/ideal.hpp"
#include "reference/psf.hpp"

using pfx_bloom::Settings;
namespace fft = pfx_bloom::fft;

namespace {

Settings defaults(int mode) {
  pfx_value values[pfx_bloom::PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_bloom::PARAM_COUNT; ++i) values[i] = pfx_bloom::kParams[i].default_value;
  values[pfx_bloom::PARAM_MODE].v[0] = mode;
  return pfx_bloom::settings_from(values);
}

double tap(const fft::Kernel& k, int dx, int dy) {
  const int x = k.cx + dx, y = k.cy + dy;
  return x >= 0 && y >= 0 && x < k.w && y < k.h ? k.at(x, y) : 0.0;
}

struct Moments {
  double sum = 0, mean_x = 0, mean_y = 0, variance_x = 0;
};

Moments moments(const fft::Kernel& k) {
  Moments m;
  for (int y = 0; y < k.h; ++y)
    for (int x = 0; x < k.w; ++x) {
      const double v = k.at(x, y), dx = x - k.cx, dy = y - k.cy;
      m.sum += v, m.mean_x += v * dx, m.mean_y += v * dy, m.variance_x += v * dx * dx;
    }
  m.mean_x /= m.sum, m.mean_y /= m.sum, m.variance_x = m.variance_x / m.sum - m.mean_x * m.mean_x;
  return m;
}

}  // namespace

TEST_CASE("the FFT convolution equals the direct sum, wide kernels included", "[bloom][ideal]") {
  const int w = 23, h = 17;
  for (auto [kw, kh, cx, cy] : {std::tuple{5, 3, 2, 1}, std::tuple{9, 40, 1, 30}, std::tuple{60, 50, 30, 20}}) {
    fft::Kernel k;
    k.w = kw, k.h = kh, k.cx = cx, k.cy = cy;
    for (int i = 0; i < kw * kh; ++i) k.taps.push_back(std::sin(i * 1.7) + 0.3);
    std::vector<double> a(size_t(w) * h), b(a.size()), c(a.size());
    for (size_t i = 0; i < a.size(); ++i) a[i] = std::cos(double(i)) * 3, b[i] = double(i % 7), c[i] = i == 40 ? 1.0 : 0.0;
    std::vector<double> fa = a, fb = b, fc = c;
    fft::convolve({&fa, &fb, &fc}, w, h, k);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double da = 0, db = 0, dc = 0;
        for (int j = 0; j < kh; ++j)
          for (int i = 0; i < kw; ++i) {
            const int sx = x + cx - i, sy = y + cy - j;
            if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
            const size_t s = size_t(sy) * w + sx;
            da += k.at(i, j) * a[s], db += k.at(i, j) * b[s], dc += k.at(i, j) * c[s];
          }
        const size_t o = size_t(y) * w + x;
        REQUIRE(fa[o] == Approx(da).margin(1e-9));
        REQUIRE(fb[o] == Approx(db).margin(1e-9));
        REQUIRE(fc[o] == Approx(dc).margin(1e-9));
      }
  }
}

TEST_CASE("the chain's ideal PSF is the phase average of its own model's point responses", "[bloom][ideal]") {
  // Threshold 0 makes the chain linear; a point light at each of the M x M positions of the
  // coarsest grid, the responses aligned on the light and averaged, is the shift-invariant PSF.
  for (int levels : {1, 2, 3}) {
    Settings s = defaults(pfx_bloom::MODE_CHAIN);
    s.threshold = 0.0;
    s.levels = levels;
    const int size = 96, reach = 30, period = 1 << levels;
    std::vector<double> average(size_t(2 * reach + 1) * (2 * reach + 1), 0.0);
    for (int py = 40; py < 40 + period; ++py)
      for (int px = 40; px < 40 + period; ++px) {
        std::vector<float> in(size_t(size) * size * 4, 0.0f), out(in.size());
        in[(size_t(py) * size + px) * 4] = 1.0f;
        pfx_bloom::evaluate_model(s, size, size, in.data(), out.data());
        for (int dy = -reach; dy <= reach; ++dy)
          for (int dx = -reach; dx <= reach; ++dx)
            average[size_t(dy + reach) * (2 * reach + 1) + dx + reach] +=
                (out[(size_t(py + dy) * size + px + dx) * 4] - in[(size_t(py + dy) * size + px + dx) * 4]) / (period * period);
      }
    const fft::Kernel k = pfx_bloom::psf::of_mode(s, levels, size, size);
    INFO(levels << " levels");
    CHECK(moments(k).sum == Approx(1.0).margin(1e-12));
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx)
        REQUIRE(tap(k, dx, dy) == Approx(average[size_t(dy + reach) * (2 * reach + 1) + dx + reach]).margin(2e-7));
  }
}

TEST_CASE("the pyramids' PSFs keep the light and are centred, the Gaussians have their variance", "[bloom][ideal]") {
  for (int level = 0; level < 5; ++level)
    for (int mode : {pfx_bloom::MODE_CHAIN, pfx_bloom::MODE_CHAIN13}) {
      const Moments m = moments(pfx_bloom::psf::chain_level(mode, level));
      INFO("mode " << mode << " level " << level);
      CHECK(m.sum == Approx(1.0).margin(1e-12));
      CHECK(m.mean_x == Approx(0.0).margin(1e-9));
      CHECK(m.mean_y == Approx(0.0).margin(1e-9));
    }
  // Each tap integrates the continuous Gaussian over its pixel: variance sigma^2 + 1/12.
  for (double sigma : {1.5, 3.0, 25.0}) {  // (below about 1 the pixel grid itself aliases the moment)
    const Moments m = moments(pfx_bloom::psf::gaussian(sigma, 800, 800));
    CHECK(m.sum == Approx(1.0).margin(1e-9));
    CHECK(m.variance_x == Approx(sigma * sigma + 1.0 / 12).epsilon(1e-6));
  }
  // mgf: 3 buffers, weights 1, 2, 4 over 7, deviations of the cascade 10, sqrt(10^2 + 20^2), ...
  Settings s = defaults(pfx_bloom::MODE_MGF);
  const Moments m = moments(pfx_bloom::psf::of_mode(s, 3, 1000, 1000));
  const double v0 = 100, v1 = 100 + 400, v2 = 100 + 400 + 1600;
  CHECK(m.sum == Approx(1.0).margin(1e-9));
  CHECK(m.variance_x == Approx((1 * v0 + 2 * v1 + 4 * v2) / 7.0 + 1.0 / 12).epsilon(1e-6));
}

TEST_CASE("where a mode is exact its ideal and its model agree", "[bloom][ideal]") {
  // gaussian at full resolution with taps past 6 sigma samples the same Gaussian the ideal
  // integrates: they differ by the variance of a pixel (1/12 against sigma^2 = 16, about 0.3%).
  Settings s = defaults(pfx_bloom::MODE_GAUSSIAN);
  s.downscale = 1;
  s.sigma = 4.0;
  s.half_taps = 25;
  s.threshold = 0.5;
  const int w = 80, h = 60;
  std::vector<float> in(size_t(w) * h * 4, 0.0f), model(in.size()), ideal(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* c = &in[(size_t(y) * w + x) * 4];
      c[0] = float((x * 7 + y * 3) % 11) / 4.0f;
      c[1] = (x - 40) * (x - 40) + (y - 30) * (y - 30) < 30 ? 20.0f : 0.25f;
      c[2] = 1.0f;
    }
  pfx_bloom::evaluate_model(s, w, h, in.data(), model.data());
  pfx_bloom::evaluate_ideal(s, w, h, in.data(), ideal.data());
  double error = 0, bloom = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    if (i % 4 == 3) continue;
    error += (model[i] - ideal[i]) * double(model[i] - ideal[i]);
    bloom += (ideal[i] - in[i]) * double(ideal[i] - in[i]);
  }
  CHECK(std::sqrt(error / bloom) < 0.01);
  CHECK(std::sqrt(error / bloom) > 1e-5);  // they are not the same computation
}
