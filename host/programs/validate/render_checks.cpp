#include "render_checks.hpp"

#include <algorithm>
#include <cmath>

#include <pfx/host/frame_plan.hpp>

#include "camera_options.hpp"
#include "frame_description.hpp"
#include "random_params.hpp"
#include "render_rig.hpp"
#include "synthetic_inputs.hpp"

namespace pfx::validate {
namespace {

bool open_with_effect(RenderRig& rig, const std::string& path, const std::string& effect_id) {
  return rig.open(path) && rig.add_effect(effect_id);
}

// "bloom.threshold=1.5 bloom.mode=chain": the set as pfx-render --set arguments.
std::string describe_values(RenderRig& rig, const std::string& effect_id) {
  std::string text;
  const pfx_effect_desc* desc = rig.effect();
  for (uint32_t i = 0; i < desc->param_count; ++i) {
    const std::string key = effect_id + "." + desc->params[i].id;
    text += (text.empty() ? "" : " ") + key + "=" + rig.params().get_text(key);
  }
  return text.empty() ? "(no parameters)" : text;
}

// With the values the store holds now: an effect that promises PFX_EFFECT_COLOR_ONLY must ask a
// frame of colour alone for nothing more, since hosts of video frames offer it on that promise
// without asking. `set` names the values for the message.
void check_colour_promise(RenderRig& rig, const std::string& set, CheckReporter& report) {
  if (!(rig.effect()->flags & PFX_EFFECT_COLOR_ONLY)) return;
  const pfx_frame frame = pfx::app::describe_frame(64, 48, PFX_INPUT_COLOR, PFX_DEPTH_NONE,
                                                   pfx::app::make_camera(pfx::app::CameraOptions{}, 64, 48));
  uint32_t inputs = 0;
  std::string error;
  if (!rig.chain().inputs_needed(0, frame, &inputs, &error)) {
    report.problem(set + ": declare failed for a frame of colour alone: " + error);
    return;
  }
  const uint32_t more = inputs & ~static_cast<uint32_t>(PFX_INPUT_COLOR);
  if (more)
    report.problem("it promises PFX_EFFECT_COLOR_ONLY, but with " + set + " it asks a frame of colour alone for " +
                   pfx::host::frame_input_names(more) + ": hosts of video frames offer it on that promise without asking");
}

}  // namespace

void check_create_destroy(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  RenderRig rig(report);
  if (!open_with_effect(rig, path, effect_id)) return;
  rig.remove_effect();
  if (!rig.add_effect(effect_id)) return;
  rig.render(gradient_image(16, 9), "gradient 16x9 after a destroy and a second create");
  rig.remove_effect();
}

void check_defaults(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  RenderRig rig(report);
  if (!open_with_effect(rig, path, effect_id)) return;
  for (const SyntheticInput& input : default_inputs()) rig.render(input.image, input.name + " (defaults)");
}

void check_random(const std::string& path, const std::string& effect_id, uint64_t seed, int runs,
                  CheckReporter& report) {
  RenderRig rig(report);
  if (!open_with_effect(rig, path, effect_id)) return;
  const pfx_effect_desc* desc = rig.effect();
  SplitMix64 rng(seed);
  const pfx::app::Image gradient = gradient_image(48, 32);
  const pfx::app::Image hostile = hostile_image(37, 23);
  check_colour_promise(rig, "its defaults", report);
  for (int run = 0; run < runs; ++run) {
    const std::vector<pfx_value> values = random_parameter_set(*desc, rng);
    const std::string set = "random set " + std::to_string(run + 1) + " of seed " + std::to_string(seed);
    bool applied = true;
    for (uint32_t i = 0; i < desc->param_count; ++i) {
      std::string error;
      if (!rig.params().set_value(effect_id, desc->params[i].id, values[i], &error)) {
        report.problem(set + ": the host refused a value inside the hard range: " + error);
        applied = false;
      }
    }
    if (!applied) continue;
    const std::string values_text = describe_values(rig, effect_id);
    report.fact("set", std::to_string(run + 1) + ": " + values_text);
    rig.render(gradient, set + " on gradient 48x32 [" + values_text + "]");
    rig.render(hostile, set + " on NaN/Inf/70000 37x23 [" + values_text + "]");
    check_colour_promise(rig, set, report);
  }
}

void check_resize(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  RenderRig rig(report);
  if (!open_with_effect(rig, path, effect_id)) return;
  const pfx::app::Image first_input = gradient_image(64, 48);
  pfx::app::Image first, last;
  if (!rig.render(first_input, "64x48 (first)", &first)) return;
  for (const auto& [w, h] : {std::pair{1917, 1079}, std::pair{1, 1}, std::pair{33, 17}})
    rig.render(gradient_image(w, h), std::to_string(w) + "x" + std::to_string(h) + " after a resize");
  if (!rig.render(first_input, "64x48 again after the resizes", &last)) return;
  // The same frame with the same settings: anything but rounding means state survived the
  // resizes (a stale target, a size cached in create). Half-float storage: 2^-10 relative.
  double worst = 0;
  size_t worst_at = 0;
  for (size_t i = 0; i < first.rgba.size(); ++i) {
    const double a = first.rgba[i], b = last.rgba[i];
    if (std::isnan(a) && std::isnan(b)) continue;
    const double diff = std::fabs(a - b) / std::max(1.0, std::fabs(a));
    if (!(diff <= worst)) {
      worst = std::isnan(diff) ? INFINITY : diff;
      worst_at = i;
    }
  }
  if (worst > 2e-3)
    report.problem("64x48 rendered again after the resizes differs from the first 64x48 frame by " +
                   std::to_string(worst) + " (relative) at x=" + std::to_string(worst_at / 4 % 64) +
                   ", y=" + std::to_string(worst_at / 4 / 64) + " channel " + std::to_string(worst_at % 4));
}

namespace {

// A display frame at 61x37 (odd, so a pyramid's edges show): smooth ramps, a dark corner where
// the sRGB curve is steepest, and a bright block for effects that respond to highlights.
pfx::app::DisplayImage display_codes() {
  const int w = 61, h = 37;
  pfx::app::DisplayImage codes;
  codes.width = w;
  codes.height = h;
  codes.channels = 4;
  codes.pixels.resize(static_cast<size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &codes.pixels[(static_cast<size_t>(y) * w + x) * 4];
      const bool block = x > 38 && x < 48 && y > 8 && y < 20;
      p[0] = block ? 255 : static_cast<uint8_t>(x * 255 / (w - 1));
      p[1] = block ? 250 : static_cast<uint8_t>(y * 255 / (h - 1));
      p[2] = block ? 240 : static_cast<uint8_t>(x < 8 && y < 8 ? x + y : (x * y) % 256);
      p[3] = 255;
    }
  return codes;
}

}  // namespace

void check_display_frame(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  RenderRig rig(report, pfx::host::DefaultSet::DISPLAY_REFERRED);
  if (!open_with_effect(rig, path, effect_id)) return;
  const pfx::app::DisplayImage codes = display_codes();
  pfx::app::DisplayImage eight_bit, wide;
  int own_passes = 0;
  if (!rig.render_display(codes, "a 61x37 display frame", &eight_bit, &wide, &own_passes)) return;
  if (rig.chain().report().passes.empty()) {
    report.fact("skip", "with its display-referred defaults the effect runs no pass over an 8-bit frame");
    return;
  }
  if (own_passes > 0) {
    report.fact("skip", "the effect does not promise PFX_DECLARATION_SAMPLES_AND_DRAWS: the chain converts an "
                        "8-bit frame for it");
    return;
  }
  int worst = 0;
  size_t worst_at = 0;
  for (size_t i = 0; i < wide.pixels.size(); ++i) {
    const int diff = std::abs(int(eight_bit.pixels[i]) - int(wide.pixels[i]));
    if (diff > worst) {
      worst = diff;
      worst_at = i;
    }
  }
  report.fact("display_frame_codes", std::to_string(worst));
  if (worst > kDisplayFrameCodes)
    report.problem("it promises PFX_DECLARATION_SAMPLES_AND_DRAWS, but over an 8-bit frame handed as 8-bit textures "
                   "it gives up to " + std::to_string(worst) + " codes away from the same frame in RGBA16F (at x=" +
                   std::to_string(worst_at / 4 % codes.width) + ", y=" + std::to_string(worst_at / 4 / codes.width) +
                   " from the top, channel " + std::to_string(worst_at % 4) + "; at most " +
                   std::to_string(kDisplayFrameCodes) + " allowed): does a pass read colour or write output other "
                   "than by sampling and drawing?");
}

}  // namespace pfx::validate
