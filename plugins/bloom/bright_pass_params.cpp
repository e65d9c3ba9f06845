#include "bright_pass_params.hpp"

#include <pfx/cpp/descriptors.hpp>

#include "bloom_params.hpp"

namespace pfx_bloom {
namespace {

const pfx_enum_item kMeasureItems[] = {{"max_rgb", "Largest of R, G, B"}, {"luminance", "Rec. 709 luminance"}};
const pfx_enum_item kNonfiniteItems[] = {
    {"zero", "A pixel with NaN or +-Inf in R, G or B is black: it adds no light and shows black"},
    {"clamp", "NaN -> 0, +-Inf -> +-65504 per channel: +Inf blooms as the firefly clamp"}};

}  // namespace

// Hard ranges are finite so "inf" from a user clamps to something the shaders can use. Threshold
// and knee stop at the half-float maximum: no stored colour is brighter than that.
//
// Display-referred frames (8-bit video, a back buffer) hold nothing above 1.0, so the scene-linear
// threshold of diffuse white would never be passed there: each effect gives its own start for such
// frames (bloom lets the top of the range glow, glare only near-white highlights). docs/effects/
// bloom.md says how they were chosen, with the shares of pixels they reach in real frames.
pfx_param_desc threshold_param(double display_default) {
  return pfx::desc::param("threshold")
      .label("Threshold")
      .group("Bright pass")
      .tooltip(
          "Brightness above which light spreads. Scene-linear: 1 is the brightness of diffuse white. "
          "On display-referred frames (8-bit video, an application's window), where nothing passes "
          "1, it starts lower (the effect's documentation says where).")
      .float_range(0, kHalfMax)
      .display_range(0, 8)
      .step(0.05)
      .default_value(1.0)
      .display_default(display_default);
}

pfx_param_desc knee_param(double display_default) {
  return pfx::desc::param("knee")
      .label("Knee")
      .group("Bright pass")
      .tooltip(
          "Width of the soft transition around the threshold: brightness from threshold - knee to "
          "threshold + knee spreads gradually (quadratic). 0 is a hard threshold; the knee "
          "is never wider than the threshold. On display-referred frames it starts wider than 0.")
      .float_range(0, kHalfMax)
      .display_range(0, 2)
      .step(0.05)
      .default_value(0.0)
      .display_default(display_default);
}

pfx_param_desc measure_param(const char* tooltip) {
  return pfx::desc::param("measure")
      .label("Brightness measure")
      .group("Bright pass")
      .tooltip(tooltip)
      .items(kMeasureItems, 2)
      .default_value(MEASURE_MAX_RGB);
}

pfx_param_desc firefly_clamp_param() {
  return pfx::desc::param("firefly_clamp")
      .label("Firefly clamp")
      .group("Bright pass")
      .tooltip(
          "Every colour channel is clamped to this before the bright pass, so single very bright "
          "pixels cannot dominate (with nonfinite=clamp, infinite ones too).")
      .float_range(0, kHalfMax)
      .display_range(1, kHalfMax)
      .step(1)
      .default_value(65472.0);
}

pfx_param_desc nonfinite_param() {
  return pfx::desc::param("nonfinite")
      .label("Non-finite pixels")
      .group("Bright pass")
      .tooltip(
          "What a pixel holding NaN or +-Inf (a renderer's failed sample) counts as, before any "
          "filtering. zero: the whole pixel is black, in the light it spreads and in the output. "
          "clamp: NaN counts as 0 and +-Inf as +-65504 channel by channel, so +Inf blooms as the "
          "brightest light the firefly clamp allows.")
      .items(kNonfiniteItems, 2)
      .default_value(NONFINITE_ZERO);
}

}  // namespace pfx_bloom
