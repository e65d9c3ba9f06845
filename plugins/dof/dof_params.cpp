#include "dof_params.hpp"

#include <pfx/cpp/descriptors.hpp>

namespace pfx_dof {
namespace {

const pfx_enum_item kModeItems[] = {
    {"seed", "Seed: 16-tap disk from a half-size copy, mixed in as the CoC passes 1 px"},
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

pfx_param_desc logarithmic(pfx_param_desc d) {
  d.flags |= PFX_PARAM_LOGARITHMIC;
  return d;
}

}  // namespace

const pfx_param_desc kParams[PARAM_COUNT] = {
    pfx::desc::with_items(
        pfx::desc::param("mode", "Mode",
                         "seed: the seed's 16-tap disk from a half-size copy, blended in as the blur passes 1 px "
                         "(halos around in-focus objects). gather: the quality mode, with separate near and far "
                         "fields, ring samples sized per 16 px tile, and in-focus tiles left exactly as they were.",
                         "", "Depth of field", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{MODE_GATHER}}),
        kModeItems, 2),
    logarithmic(pfx::desc::param(
        "focus_distance", "Focus distance",
        "Distance from the lens to the plane in perfect focus, in metres along the view axis. Ignored while "
        "autofocus is on. 'inf' focuses at infinity (clamped to 1e9 m, which is the same to within 1e-6 px).",
        "m", "Camera", PFX_PARAM_FLOAT, kMinFocusDistance, kMaxFocusDistance, 0.1, 100, 0.01, {{10.0}})),
    // A display-referred frame comes from a program whose camera the host does not know (an
    // application's window, a video), so a focus distance in metres means nothing there: such
    // frames start focused on whatever is under the focus point, the centre of the picture.
    pfx::desc::with_display_default(
        pfx::desc::with_items(
            pfx::desc::param("autofocus", "Autofocus",
                             "point: focus at the depth found under the focus point each frame (the sky focuses "
                             "at infinity). off: use the focus distance. On display-referred frames (an "
                             "application's window, a video), whose camera is unknown, it starts at point.",
                             "", "Camera", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{AUTOFOCUS_OFF}}),
            kAutofocusItems, 2),
        {{AUTOFOCUS_POINT}}),
    pfx::desc::param("focus_point", "Focus point",
                     "Where autofocus reads the depth: 0..1 across the frame from the top-left corner "
                     "(0.5, 0.5 is the centre).",
                     "", "Camera", PFX_PARAM_VEC2, 0, 1, 0, 1, 0.01, {{0.5, 0.5}}),
    logarithmic(pfx::desc::param(
        "f_number", "f-number",
        "Focal length divided by the aperture diameter: smaller opens the lens and blurs more. Real lenses stop "
        "near 1; the seed's strong blur used 0.05.",
        "", "Camera", PFX_PARAM_FLOAT, kMinFNumber, kMaxFNumber, 0.7, 22, 0.1, {{1.4}})),
    pfx::desc::param("sensor_width", "Sensor width",
                     "Width of the camera's sensor. With the frame's field of view it sets the focal length; "
                     "36 mm is full frame.",
                     "mm", "Camera", PFX_PARAM_FLOAT, 1, 100, 4, 70, 0.5, {{36.0}}),
    pfx::desc::param("max_coc", "Maximum blur",
                     "The circle of confusion's diameter is clamped to this many pixels (at the frame's "
                     "resolution), in both modes; it also bounds how far the gather looks.",
                     "px", "Depth of field", PFX_PARAM_FLOAT, 1, kMaxCocLimit, 4, 64, 1, {{32.0}}),
    pfx::desc::param("samples", "Samples",
                     "gather mode: samples per pixel, in rings sized to the tile's largest blur (the quality "
                     "knob: 16, 32, 64, 128...). The seed mode always takes 16.",
                     "", "Quality", PFX_PARAM_INT, kMinSamples, kMaxSamples, 16, 128, 1, {{32}}),
    pfx::desc::with_items(
        pfx::desc::param("resolution", "Working resolution",
                         "gather mode: gather at half resolution (4x fewer samples, composited over the sharp "
                         "frame at full resolution) or at full resolution. The seed mode always blurs a "
                         "half-size copy.",
                         "", "Quality", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{RESOLUTION_HALF}}),
        kResolutionItems, 2),
    pfx::desc::with_items(
        pfx::desc::param("nonfinite", "Non-finite pixels",
                         "What a pixel holding NaN or +-Inf (a renderer's failed sample) counts as, before any "
                         "filtering. zero: the whole pixel is black, in what the blur spreads and in the output. "
                         "clamp: NaN counts as 0 and +-Inf as +-65504 channel by channel, so a +Inf pixel spreads "
                         "over its whole circle of confusion at that brightness.",
                         "", "Quality", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{NONFINITE_ZERO}}),
        kNonfiniteItems, 2),
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
