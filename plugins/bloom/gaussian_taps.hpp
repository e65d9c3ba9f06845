// The discrete Gaussians the gaussian and mgf modes blur with, shared by the shaders' uniforms and
// the CPU model so both use the very same weights.
#pragma once

namespace pfx_bloom {

struct Settings;

// The normalised weights of a Gaussian of this deviation (texels) at the centre and at 1 ..
// half_taps texels on each side: weights[0] + 2 * sum(weights[1..]) = 1. A deviation near 0 gives
// a single tap.
void gaussian_weights(double deviation, int half_taps, double* weights);

// The gaussian mode's blur deviation in texels of its downscaled buffer. The block average going
// down and the bilinear upsample coming back add variances of (d^2 - 1) / 12 and (d^2 - 1) / 6
// frame pixels^2 (d the downscale), so the blur itself takes sigma^2 - (d^2 - 1) / 4 and the whole
// comes out as close to the asked sigma as the downscale allows.
double gaussian_mode_deviation(const Settings& s);

}  // namespace pfx_bloom
