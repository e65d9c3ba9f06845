// The point spread functions the bloom modes approximate (PFX_REFERENCE_IDEAL, ideal.cpp), as 2-D
// kernels normalised to sum to 1, truncated where they can no longer pair two pixels of a
// frame_w x frame_h frame.
//
// - gaussian: the exact Gaussian of standard deviation sigma (frame pixels), each tap the integral
//   of the continuous Gaussian over its pixel (erf), i.e. the continuous kernel on a pixel grid.
// - mgf: sum over the buffers of w_i times that Gaussian with the deviation Kawase's cascade
//   gives buffer i: sigma_i^2 = sum_{j <= i} (2.5 * 4 * 2^j)^2 frame pixels^2.
// - chain, chain13: the pyramid's own PSF averaged over sub-pixel positions. For each level i the
//   path frame -> level i -> frame is a filter F_i at the frame's rate followed by decimation by
//   M = 2^(i+1), then zero-insertion and an interpolation filter G_i; averaged over the M x M
//   positions of a point light it is exactly K_i(t) = sum_k F_i(k) G_i(k + t) / M^2. F_i and G_i
//   are composed from the stages' bilinear taps on an unbounded frame with exact halving
//   (F_i = F_{i-1} * (stage up-sampled by 2^i), likewise G_i), and the levels are averaged. The
//   Karis average, the threshold on filtered taps and the caps are left out: they are what makes
//   the chain differ from a convolution.
#pragma once

#include "bloom_params.hpp"
#include "reference/fft_convolution.hpp"

namespace pfx_bloom::psf {

fft::Kernel gaussian(double sigma, int frame_w, int frame_h);

// The PSF of the settings' mode with `levels` levels (buffers for mgf; ignored by gaussian).
fft::Kernel of_mode(const Settings& s, int levels, int frame_w, int frame_h);

// The averaged PSF of one level's path of a pyramid mode (chain or chain13), for the tests.
fft::Kernel chain_level(int mode, int level);

}  // namespace pfx_bloom::psf
