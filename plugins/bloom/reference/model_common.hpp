// What the CPU models of every mode share: double-precision images, GL_LINEAR sampling with the GL
// wrap modes, and the bright pass's treatment of bad values and its threshold curve, written
// independently of the shaders (shaders_common.cpp) from the same definitions.
#pragma once

#include <cstddef>
#include <vector>

#include "bloom_params.hpp"

namespace pfx_bloom::model {

enum class Wrap { Border, Edge };

// An RGB image of doubles, rows bottom first.
struct Plane {
  int w = 0, h = 0;
  std::vector<double> rgb;
  Plane() = default;
  Plane(int width, int height) : w(width), h(height), rgb(static_cast<size_t>(width) * height * 3, 0.0) {}
  double* at(int x, int y) { return &rgb[(static_cast<size_t>(y) * w + x) * 3]; }
  const double* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * w + x) * 3]; }
};

// The largest channel value in p.
double largest(const Plane& p);

// The texel (x, y) under a wrap mode: clamp-to-border reads transparent black outside.
void texel(const Plane& p, int x, int y, Wrap wrap, double out[3]);

// GL_LINEAR at (px, py) in texels, texel centres at +0.5 (GL 4.5 §8.14.2), exact weights.
void bilinear(const Plane& p, double px, double py, Wrap wrap, double out[3]);

// The centre of pixel (x, y) of a w x h image, in texels of src.
inline double centre_x(int x, int w, const Plane& src) { return (x + 0.5) / w * src.w; }
inline double centre_y(int y, int h, const Plane& src) { return (y + 0.5) / h * src.h; }

// Whether v is NaN or +-Inf.
bool not_finite(float v);

// What the bright passes read from the frame: a pixel with NaN or +-Inf in R, G or B black
// (nonfinite zero) or NaN -> 0 per channel (clamp); then negative -> 0, at most the clamp (+Inf too).
Plane safe_frame(const float* color, int w, int h, double clamp_to, int nonfinite);

// The measures the bright pass knows: the settings' (max-RGB or luminance, with the pyramid's ratio)
// or every channel on its own (the separable Gaussian bloom).
constexpr int kMeasurePerChannel = 2;

// The threshold curve: max(b - t, 0), softened by the knee.
double soft_part(const Settings& s, double b);

// c replaced by its bright part under the measure.
void bright_part(const Settings& s, int measure, double c[3]);

// A w x h buffer whose texel (x, y) is the mean bright part of the block x block pixels of the frame
// from (x, y) * block - (pad_x, pad_y), black outside the frame, times gain, at most cap. karis:
// each pixel weighted by 1 / (1 + luma of its bright part), the sum divided by the weights'.
Plane box_bright(const Settings& s, int measure, const Plane& frame, int w, int h, int block, int pad_x, int pad_y,
                 const double gain[3], double cap, bool karis = false);

// Karis's weight of a bright part: 1 / (1 + Rec. 709 luma).
double karis_weight(const double c[3]);

// Where the centre of frame pixel (x, y) lies on a grid of texels `scale` frame pixels wide whose
// texel 0 starts `pad` pixels before the frame, in texels.
inline double on_grid(int x, int pad, int scale) { return (x + pad + 0.5) / scale; }

// NaN -> 0, +-Inf and beyond -> +-65504.
double finite_signed(float v);

// The frame's pixel as the composite passes it on: nonfinite zero: RGB black if R, G or B is NaN or
// +-Inf, a non-finite alpha 0; clamp: finite_signed per channel; both at most +-65504.
void finite_pixel(const float* rgba, int nonfinite, double out[4]);

// output = finite(frame) * frame_scale + bloom(x, y) in RGB, at most 65504 (at least -65504),
// alpha finite(frame alpha). bloom writes the added light of pixel (x, y) into its out[3].
template <typename BloomAt>
void composite(const float* color, int w, int h, double frame_scale, int nonfinite, float* output, BloomAt&& bloom) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t k = (static_cast<size_t>(y) * w + x) * 4;
      double add[3], frame[4];
      bloom(x, y, add);
      finite_pixel(color + k, nonfinite, frame);
      for (int c = 0; c < 3; ++c) {
        const double v = frame[c] * frame_scale + add[c];
        output[k + c] = static_cast<float>(v > kHalfMax ? kHalfMax : v < -kHalfMax ? -kHalfMax : v);
      }
      output[k + 3] = static_cast<float>(frame[3]);
    }
}

}  // namespace pfx_bloom::model
