// 2-D convolution with zero padding by the fast Fourier transform, in double precision: what the
// ideal references (ideal.cpp) need to convolve a full frame with a point spread function hundreds
// of pixels wide. Written here (radix-2, iterative) rather than taken from a library.
#pragma once

#include <cstddef>
#include <vector>

namespace pfx_bloom::fft {

// A kernel of w x h taps, rows bottom first; tap (cx, cy) is the one that maps a pixel onto itself.
struct Kernel {
  int w = 0, h = 0, cx = 0, cy = 0;
  std::vector<double> taps;
  double& at(int x, int y) { return taps[static_cast<size_t>(y) * w + x]; }
  double at(int x, int y) const { return taps[static_cast<size_t>(y) * w + x]; }
};

// out(x, y) = sum over (i, j) of kernel(i, j) * in(x + cx - i, y + cy - j), with in = 0 outside the
// w x h image. planes: images of w * h doubles, convolved in place. Taps more than w - 1 (h - 1)
// from the centre can never pair two pixels of the image and are ignored, so a kernel wider than
// the frame costs no more than one twice its size.
void convolve(std::vector<std::vector<double>*> planes, int w, int h, const Kernel& kernel);

// The full 2-D convolution of two kernels (sizes add up, centres add up): directly when a is small
// or sparse, else by FFT.
Kernel convolve_kernels(const Kernel& a, const Kernel& b);

// k(-x, -y): convolving with reversed(f) correlates with f.
Kernel reversed(const Kernel& k);

}  // namespace pfx_bloom::fft
