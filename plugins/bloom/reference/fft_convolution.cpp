#include "reference/fft_convolution.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace pfx_bloom::fft {
namespace {

using Complex = std::complex<double>;

int next_power_of_two(int n) {
  int p = 1;
  while (p < n) p <<= 1;
  return p;
}

// In-place FFT of n (a power of two) contiguous values; the inverse without the 1/n.
void transform(Complex* data, int n, bool inverse, std::vector<Complex>& scratch) {
  scratch.assign(data, data + n);
  for (int i = 1, j = 0; i < n; ++i) {  // bit reversal
    int bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(scratch[static_cast<size_t>(i)], scratch[static_cast<size_t>(j)]);
  }
  const double sign = inverse ? 1.0 : -1.0;
  for (int len = 2; len <= n; len <<= 1) {
    const double angle = sign * 2.0 * 3.14159265358979323846 / len;
    const Complex step(std::cos(angle), std::sin(angle));
    for (int start = 0; start < n; start += len) {
      Complex w(1.0, 0.0);
      for (int k = 0; k < len / 2; ++k) {
        Complex& a = scratch[static_cast<size_t>(start + k)];
        Complex& b = scratch[static_cast<size_t>(start + k + len / 2)];
        const Complex t = b * w;
        b = a - t;
        a += t;
        // Recomputing the twiddle every 64 steps keeps its rounding from piling up along long rows.
        w = (k + 1) % 64 == 0 ? Complex(std::cos(angle * (k + 1)), std::sin(angle * (k + 1))) : w * step;
      }
    }
  }
  std::copy(scratch.begin(), scratch.end(), data);
}

// Rows, then columns, of a pw x ph grid.
void transform_2d(std::vector<Complex>& grid, int pw, int ph, bool inverse) {
  std::vector<Complex> scratch, column(static_cast<size_t>(ph));
  for (int y = 0; y < ph; ++y) transform(&grid[static_cast<size_t>(y) * pw], pw, inverse, scratch);
  for (int x = 0; x < pw; ++x) {
    for (int y = 0; y < ph; ++y) column[static_cast<size_t>(y)] = grid[static_cast<size_t>(y) * pw + x];
    transform(column.data(), ph, inverse, scratch);
    for (int y = 0; y < ph; ++y) grid[static_cast<size_t>(y) * pw + x] = column[static_cast<size_t>(y)];
  }
}

}  // namespace

void convolve(std::vector<std::vector<double>*> planes, int w, int h, const Kernel& kernel) {
  // A circular convolution of period p equals the linear one on the image when p >= w + (the span
  // of offsets used), and the offsets that matter lie within (-w, w): hence the period.
  const int span_x = std::min(kernel.w - 1, 2 * w - 2), span_y = std::min(kernel.h - 1, 2 * h - 2);
  const int pw = next_power_of_two(w + span_x), ph = next_power_of_two(h + span_y);
  std::vector<Complex> k(static_cast<size_t>(pw) * ph);
  for (int y = 0; y < kernel.h; ++y)
    for (int x = 0; x < kernel.w; ++x) {
      const int dx = x - kernel.cx, dy = y - kernel.cy;  // the offset this tap moves light by
      if (dx <= -w || dx >= w || dy <= -h || dy >= h) continue;
      k[static_cast<size_t>((dy + ph) % ph) * pw + static_cast<size_t>((dx + pw) % pw)] += kernel.at(x, y);
    }
  transform_2d(k, pw, ph, false);
  // Two real planes ride in one complex transform (real and imaginary parts): the kernel is real,
  // so they come back apart.
  for (size_t first = 0; first < planes.size(); first += 2) {
    std::vector<double>* a = planes[first];
    std::vector<double>* b = first + 1 < planes.size() ? planes[first + 1] : nullptr;
    std::vector<Complex> g(static_cast<size_t>(pw) * ph);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        g[static_cast<size_t>(y) * pw + x] = Complex((*a)[i], b ? (*b)[i] : 0.0);
      }
    transform_2d(g, pw, ph, false);
    for (size_t i = 0; i < g.size(); ++i) g[i] *= k[i];
    transform_2d(g, pw, ph, true);
    const double scale = 1.0 / (static_cast<double>(pw) * ph);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Complex v = g[static_cast<size_t>(y) * pw + x] * scale;
        const size_t i = static_cast<size_t>(y) * w + x;
        (*a)[i] = v.real();
        if (b) (*b)[i] = v.imag();
      }
  }
}

Kernel convolve_kernels(const Kernel& a, const Kernel& b) {
  Kernel out;
  out.w = a.w + b.w - 1;
  out.h = a.h + b.h - 1;
  out.cx = a.cx + b.cx;
  out.cy = a.cy + b.cy;
  out.taps.assign(static_cast<size_t>(out.w) * out.h, 0.0);
  size_t nonzero_a = 0;
  for (double v : a.taps) nonzero_a += v != 0.0;
  if (nonzero_a * b.taps.size() < 50'000'000) {  // direct: exact, and fast for a sparse a
    for (int y = 0; y < a.h; ++y)
      for (int x = 0; x < a.w; ++x) {
        const double v = a.at(x, y);
        if (v == 0.0) continue;
        for (int j = 0; j < b.h; ++j)
          for (int i = 0; i < b.w; ++i) out.at(x + i, y + j) += v * b.at(i, j);
      }
    return out;
  }
  const int pw = next_power_of_two(out.w), ph = next_power_of_two(out.h);
  std::vector<Complex> fa(static_cast<size_t>(pw) * ph), fb(fa.size());
  for (int y = 0; y < a.h; ++y)
    for (int x = 0; x < a.w; ++x) fa[static_cast<size_t>(y) * pw + x] = a.at(x, y);
  for (int y = 0; y < b.h; ++y)
    for (int x = 0; x < b.w; ++x) fb[static_cast<size_t>(y) * pw + x] = b.at(x, y);
  transform_2d(fa, pw, ph, false);
  transform_2d(fb, pw, ph, false);
  for (size_t i = 0; i < fa.size(); ++i) fa[i] *= fb[i];
  transform_2d(fa, pw, ph, true);
  const double scale = 1.0 / (static_cast<double>(pw) * ph);
  for (int y = 0; y < out.h; ++y)
    for (int x = 0; x < out.w; ++x) out.at(x, y) = fa[static_cast<size_t>(y) * pw + x].real() * scale;
  return out;
}

Kernel reversed(const Kernel& k) {
  Kernel r = k;
  r.cx = k.w - 1 - k.cx;
  r.cy = k.h - 1 - k.cy;
  for (int y = 0; y < k.h; ++y)
    for (int x = 0; x < k.w; ++x) r.at(k.w - 1 - x, k.h - 1 - y) = k.at(x, y);
  return r;
}

}  // namespace pfx_bloom::fft
