// Scene-linear HDR to 8-bit sRGB for display and PNG output:
//   1. exposure: multiply by 2^exposure_ev;
//   2. a named tone curve per channel, mapping [0, inf) to display-linear [0, 1];
//   3. the exact piecewise sRGB OETF (IEC 61966-2-1), then round to nearest 8-bit value.
//
// Pixels that are not ordinary numbers get fixed, documented values so they stay visible
// instead of crashing anything or passing as plausible colour:
//   - any NaN among R, G, B  -> the whole pixel is magenta (255, 0, 255);
//   - +inf in a channel       -> that channel is 255 (fully bright), whatever the curve;
//   - negative values, -inf   -> that channel is 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.hpp"

namespace pfx::app {

enum class ToneCurve {
  Linear,    // clamp to [0, 1]
  Reinhard,  // x / (1 + x)
  Aces,      // Narkowicz 2015 fit of the ACES RRT+ODT: x(2.51x+0.03) / (x(2.43x+0.59)+0.14)
};

struct ToneMapSettings {
  double exposure_ev = 0.0;
  ToneCurve curve = ToneCurve::Linear;
};

// The value NaN pixels are shown as.
constexpr std::uint8_t kNanColour[3] = {255, 0, 255};

// Every curve name, in a stable order, for --help and error messages.
const std::vector<std::string>& tone_curve_names();
// One line per curve: "NAME  description", for --help.
std::string tone_curve_help();
const char* tone_curve_name(ToneCurve curve);
// Accepts exactly the names above. On failure sets *error to a message that lists them.
bool parse_tone_curve(const std::string& name, ToneCurve* out, std::string* error);

// Scene-linear (already exposed) to display-linear [0, 1], following the rules above for
// negative and infinite input; NaN in gives NaN out.
float apply_tone_curve(ToneCurve curve, float x);
// Display-linear [0, 1] to sRGB-encoded [0, 1] (input clamped to [0, 1]).
double srgb_oetf(double linear);
// Display-linear to the nearest 8-bit sRGB code.
std::uint8_t encode_srgb8(float display_linear);

// One pixel, following every rule above.
void tonemap_pixel(const float rgb[3], const ToneMapSettings& settings, std::uint8_t out[3]);
// The whole image to an RGB DisplayImage (alpha is dropped: the output is for viewing).
DisplayImage tonemap_to_srgb8(const Image& img, const ToneMapSettings& settings);

}  // namespace pfx::app
