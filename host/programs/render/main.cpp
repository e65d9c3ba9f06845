// pfx-render: the command-line host. Loads plugins, runs a chain of effects over one frame or a
// frame sequence (sequence_loop.hpp) headless, writes EXR/PNG and optionally a JSON report. Exit
// codes: exit_codes.hpp (docs/exit-codes.md).
//
// The steps, each in a file of its own: the chain (render_chain.hpp), the frame it runs over
// (render_input.hpp), the result written and reported (render_output.hpp); for a sequence, the
// frame plan (frame_plan.hpp) and the loop over it (sequence_loop.hpp).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "camera_settings.hpp"
#include "display_input.hpp"
#include "exit_codes.hpp"
#include "frame_plan.hpp"
#include "headless_context.hpp"
#include "plugin_directory.hpp"
#include "plugin_listing.hpp"
#include "preset.hpp"
#include "render_chain.hpp"
#include "render_input.hpp"
#include "render_options.hpp"
#include "render_output.hpp"
#include "sequence_loop.hpp"

using namespace pfx::app;
using namespace pfx::exit_code;
namespace host = pfx::host;

namespace {

int error_exit(int code, const std::string& message) {
  std::fprintf(stderr, "pfx-render: %s\n", message.c_str());
  return code;
}

// The preset's camera and display settings with the command line's over them, key by key.
struct Look {
  PresetCamera camera;
  ToneMapSettings tone;
};

Look settle_look(const RenderOptions& options, const Preset& preset) {
  Look look;
  look.camera = with_camera_keys(preset.camera, options.camera, options.camera_keys);
  look.tone = options.tone;
  if (preset.exposure_ev && !options.exposure_given) look.tone.exposure_ev = *preset.exposure_ev;
  if (preset.tone && !options.tone_given) look.tone.curve = *preset.tone;
  return look;
}

host::GlProcLoader headless_loader() {
  return [](const char* name) { return HeadlessContext::get_proc_address(nullptr, name); };
}

int list_plugins(const RenderOptions& options) {
  host::PluginRegistry registry(headless_loader(), host::stderr_log_sink(options.verbose ? PFX_LOG_DEBUG : PFX_LOG_INFO),
                                "pfx-render " PFX_VERSION);
  const std::vector<std::string> errors = load_plugins(registry, options.plugin_dirs);
  std::fputs((options.json ? plugin_listing_json(registry, errors) + "\n" : plugin_listing_text(registry, errors)).c_str(),
             stdout);
  return kOk;
}

// --demo, --scene, --demo-image or --input: one frame through the chain, written and reported.
int render_single_frame(const RenderOptions& options, const Look& look, const host::PluginRegistry& registry,
                        host::Chain& chain, DisplayInput* display, const std::string& renderer) {
  RenderInput input;
  std::string message;
  if (options.demo || !options.scene.empty()) {
    const int code = input.load_scene(options, look.camera, registry, &message);
    if (code != kOk) return error_exit(code, message);
  } else if (!input.load_image(options, options.input, options.depth, look.camera, display, &message)) {
    return error_exit(kBadInput, message);
  }
  RenderResult result;
  if (!render_frame(chain, input, display, input_transfer(options), &result, &message))
    return error_exit(kEffectError, message);
  if (!write_outputs(options.outputs, options.float_exr, look.tone, result, &message))
    return error_exit(kInternal, message);
  if (options.json) {
    const nlohmann::ordered_json read =
        options.input.empty() ? nlohmann::ordered_json() : input_json(options.input, options.depth, input.files_read());
    std::puts(report_json(renderer, input.frame(), chain.report(), result.image, options.outputs, read).dump(2).c_str());
  } else {
    print_report(renderer, chain.report(), options.input, options.depth, input.files_read());
  }
  return kOk;
}

// One frame of a sequence: its input (and depth) through the chain, which keeps its plugins,
// programs and targets from the frame before, to its outputs.
bool render_sequence_frame(const RenderOptions& options, const Look& look, const FrameFiles& files, host::Chain& chain,
                           DisplayInput* display, const std::string& renderer, nlohmann::ordered_json* report,
                           std::string* error) {
  RenderInput input;
  RenderResult result;
  if (!input.load_image(options, files.input, files.depth, look.camera, display, error)) return false;
  input.set_sequence_frame(files.frame);
  if (!render_frame(chain, input, display, input_transfer(options), &result, error) ||
      !write_outputs(files.outputs, options.float_exr, look.tone, result, error))
    return false;
  *report = report_json(renderer, input.frame(), chain.report(), result.image, files.outputs,
                        input_json(files.input, files.depth, input.files_read()));
  return true;
}

int run(const RenderOptions& options) {
  if (options.list) return list_plugins(options);
  std::string message;
  const std::unique_ptr<HeadlessContext> context = HeadlessContext::create(&message);
  if (!context) return error_exit(kInternal, message);
  host::PluginRegistry registry(headless_loader(), host::stderr_log_sink(options.verbose ? PFX_LOG_DEBUG : PFX_LOG_INFO),
                                "pfx-render " PFX_VERSION);
  for (const auto& error : load_plugins(registry, options.plugin_dirs))
    std::fprintf(stderr, "pfx-render: warning: %s\n", error.c_str());

  // A preset gives the chain, the values, the camera and the display settings; the command line
  // overrides each of them.
  Preset preset;
  if (!options.preset.empty() && !read_preset(options.preset, &preset, &message)) return error_exit(kBadInput, message);
  const Look look = settle_look(options, preset);
  RenderChain chain(registry, options, context->renderer());
  if (const int code = chain.build(options, preset, &message); code != kOk) return error_exit(code, message);

  std::unique_ptr<DisplayInput> display;
  if (has_display_input(options)) {
    display = DisplayInput::create(wants_linear_result(options.outputs), &message);
    if (!display) return error_exit(kInternal, message);
    if (preset.exposure_ev || preset.tone)
      std::fprintf(stderr, "pfx-render: note: %s: the display settings do not apply to an 8-bit input\n",
                   options.preset.c_str());
  }
  if (!options.sequence.given)
    return render_single_frame(options, look, registry, chain.chain(), display.get(), context->renderer());
  return run_sequence(options, [&](const FrameFiles& files, nlohmann::ordered_json* report, std::string* error) {
    return render_sequence_frame(options, look, files, chain.chain(), display.get(), context->renderer(), report, error);
  });
}

}  // namespace

int main(int argc, char** argv) {
  RenderOptions options;
  std::string error;
  if (!parse_render_options(std::vector<std::string>(argv + 1, argv + argc), &options, &error)) {
    std::fprintf(stderr, "pfx-render: %s\n\n%s", error.c_str(), render_usage().c_str());
    return kUsage;
  }
  if (options.help) {
    std::fputs(render_usage().c_str(), stdout);
    return kOk;
  }
  // The plan needs no GL and no plugin: pfx-farm asks it on machines without a GPU.
  if (options.sequence.print_frames) {
    std::fputs(frame_plan_json(options).c_str(), stdout);
    return kOk;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    return error_exit(kInternal, std::string("internal error: ") + e.what());
  }
}
