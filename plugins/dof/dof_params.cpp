#include "dof_params.hpp"

#include <pfx/cpp/descriptors.hpp>

namespace pfx_dof {
namespace {

const pfx_enum_item kModeItems[] = {
    {"seed", "16-tap disk from a half-size copy, mixed in as the CoC passes 1 px"},
    {"gather", "Near/far gather: 16 px CoC tiles, dilated; in-focus tiles untouched; no halos"}};

const pfx_enum_item kAutofocusItems[] = {
    {"off", "Focus at the focus distance"},
    {"point", "Focus at the depth under the focus point"}};

const pfx_enum_item kNonfiniteItems[] = {
    {"zero", "A pixel with NaN or +-Inf in R, G or B is black: it spreads no colour and shows black"},
    {"clamp", "NaN -> 0, +-Inf -> +-65504 per channel: +Inf spreads as the brightest colour"}};

const pfx_enum_item kResolutionItems[] = {
    {"half", "Gather at half resolution, composite at full"},
    {"full", "Gather at full resolution"}};

}  // namespace

const pfx_param_desc kParams[PARAM_COUNT] = {
    pfx::desc::param("mode")
        .label("Mode")
        .group("Depth of field")
        .tooltip("seed: a 16-tap disk gather from a half-size copy, blended in as the blur passes 1 px "
                 "(halos around in-focus objects). gather: the quality mode, with separate near and far "
                 "fields, ring samples sized per 16 px tile, and in-focus tiles left exactly as they were.")
        .items(kModeItems, 2)
        .default_value(MODE_GATHER),
    pfx::desc::param("focus_distance")
        .label("Focus distance")
        .unit("m")
        .group("Camera")
        .tooltip("Distance from the lens to the plane in perfect focus, in metres along the view axis. Ignored "
                 "while autofocus is on. 'inf' focuses at infinity (clamped to 1e9 m, which is the same to "
                 "within 1e-6 px).")
        .float_range(kMinFocusDistance, kMaxFocusDistance)
        .display_range(0.1, 100)
        .step(0.01)
        .logarithmic()
        .default_value(10.0),
    // A display-referred frame comes from a program whose camera the host does not know (an
    // application's window, a video), so a focus distance in metres means nothing there: such
    // frames start focused on whatever is under the focus point, the centre of the picture.
    pfx::desc::param("autofocus")
        .label("Autofocus")
        .group("Camera")
        .tooltip("point: focus at the depth found under the focus point each frame (the sky focuses "
                 "at infinity). off: use the focus distance. On display-referred frames (an "
                 "application's window, a video), whose camera is unknown, it starts at point.")
        .items(kAutofocusItems, 2)
        .default_value(AUTOFOCUS_OFF)
        .display_default(AUTOFOCUS_POINT),
    pfx::desc::param("focus_point")
        .label("Focus point")
        .group("Camera")
        .tooltip("Where autofocus reads the depth: 0..1 across the frame from the top-left corner "
                 "(0.5, 0.5 is the centre).")
        .vec2_range(0, 1)
        .step(0.01)
        .default_value(0.5, 0.5),
    pfx::desc::param("f_number")
        .label("f-number")
        .group("Camera")
        .tooltip("Focal length divided by the aperture diameter: smaller opens the lens and blurs more. Real "
                 "lenses stop near 1; 0.05 gives a strong, unrealistic blur.")
        .float_range(kMinFNumber, kMaxFNumber)
        .display_range(0.7, 22)
        .step(0.1)
        .logarithmic()
        .default_value(1.4),
    pfx::desc::param("sensor_width")
        .label("Sensor width")
        .unit("mm")
        .group("Camera")
        .tooltip("Width of the camera's sensor. With the frame's field of view it sets the focal length; "
                 "36 mm is full frame.")
        .float_range(1, 100)
        .display_range(4, 70)
        .step(0.5)
        .default_value(36.0),
    pfx::desc::param("max_coc")
        .label("Maximum blur")
        .unit("px")
        .group("Depth of field")
        .tooltip("The circle of confusion's diameter is clamped to this many pixels (at the frame's "
                 "resolution), in both modes; it also bounds how far the gather looks.")
        .float_range(1, kMaxCocLimit)
        .display_range(4, 64)
        .step(1)
        .default_value(32.0),
    pfx::desc::param("samples")
        .label("Samples")
        .group("Quality")
        .tooltip("gather mode: samples per pixel, in rings sized to the tile's largest blur (the quality "
                 "knob: 16, 32, 64, 128...). The 16-tap disk mode (seed) always takes 16.")
        .int_range(kMinSamples, kMaxSamples)
        .display_range(16, 128)
        .default_value(32),
    pfx::desc::param("resolution")
        .label("Working resolution")
        .group("Quality")
        .tooltip("gather mode: gather at half resolution (4x fewer samples, composited over the sharp "
                 "frame at full resolution) or at full resolution. The 16-tap disk mode (seed) always blurs a "
                 "half-size copy.")
        .items(kResolutionItems, 2)
        .default_value(RESOLUTION_HALF),
    pfx::desc::param("nonfinite")
        .label("Non-finite pixels")
        .group("Quality")
        .tooltip("What a pixel holding NaN or +-Inf (a renderer's failed sample) counts as, before any "
                 "filtering. zero: the whole pixel is black, in what the blur spreads and in the output. "
                 "clamp: NaN counts as 0 and +-Inf as +-65504 channel by channel, so a +Inf pixel spreads "
                 "over its whole circle of confusion at that brightness.")
        .items(kNonfiniteItems, 2)
        .default_value(NONFINITE_ZERO),
};

Settings settings_from(const pfx_value* values) {
  Settings s;
  s.mode = static_cast<int>(values[PARAM_MODE].v[0]);
  s.focus_distance = values[PARAM_FOCUS_DISTANCE].v[0];
  s.autofocus = static_cast<int>(values[PARAM_AUTOFOCUS].v[0]);
  s.focus_point[0] = values[PARAM_FOCUS_POINT].v[0];
  s.focus_point[1] = values[PARAM_FOCUS_POINT].v[1];
  s.f_number = values[PARAM_F_NUMBER].v[0];
  s.sensor_width = values[PARAM_SENSOR_WIDTH].v[0];
  s.max_coc = values[PARAM_MAX_COC].v[0];
  s.samples = static_cast<int>(values[PARAM_SAMPLES].v[0]);
  s.resolution = static_cast<int>(values[PARAM_RESOLUTION].v[0]);
  s.nonfinite = static_cast<int>(values[PARAM_NONFINITE].v[0]);
  return s;
}

}  // namespace pfx_dof
