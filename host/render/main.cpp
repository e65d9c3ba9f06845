// pfx-render: the command-line host. Loads plugins, runs a chain of effects over one frame or a
// frame sequence (sequence_loop.hpp) headless, writes EXR/PNG and optionally a JSON report. Exit
// codes in render_usage().
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <pfx/host/chain.hpp>

#include "camera_settings.hpp"
#include "cli_text.hpp"
#include "default_chain.hpp"
#include "demo_image.hpp"
#include "demo_scene.hpp"
#include "display_input.hpp"
#include "import_scene.hpp"
#include "exr_io.hpp"
#include "gbuffer.hpp"
#include "headless_context.hpp"
#include "image_stats.hpp"
#include "image_texture.hpp"
#include "input_image.hpp"
#include "plugin_directory.hpp"
#include "plugin_listing.hpp"
#include "png_io.hpp"
#include "preset.hpp"
#include "render_options.hpp"
#include "sequence_loop.hpp"
#include "timing_choice.hpp"
#include "tonemap.hpp"

using namespace pfx::app;
namespace host = pfx::host;

namespace {

enum ExitCode { kOk = 0, kInternal = 1, kUsage = 2, kBadInput = 3, kEffectError = 4 };

int error_exit(int code, const std::string& message) {
  std::fprintf(stderr, "pfx-render: %s\n", message.c_str());
  return code;
}

Transfer input_transfer(const RenderOptions& options) {
  Transfer transfer = Transfer::SRGB;
  std::string unused;
  parse_transfer(options.transfer, &transfer, &unused);  // checked with the options
  return transfer;
}

// The --input file (or the demo image) read into *image; an 8-bit input is decoded into
// display's textures instead, and *image gets only its size.
bool load_input(const RenderOptions& options, DisplayInput* display, Image* image, InputReport* report,
                std::string* error) {
  if (options.demo_image) {
    *image = make_demo_image(options.width, options.height);
    return true;
  }
  if (display) {
    if (!display->load(options.input, input_transfer(options), options.max_input_pixels, error)) return false;
    *image = Image{};
    image->width = display->width();
    image->height = display->height();
    report->color = display->description();
    return true;
  }
  InputFiles files;
  files.input = options.input;
  files.layer = options.layer;
  files.depth = options.depth;
  files.limits.max_pixels = options.max_input_pixels;
  return read_input_image(files, image, report, error);
}

// Which channels of --input (and --depth) became the frame, so a user can see what was taken
// from a file with several candidates.
nlohmann::ordered_json input_json(const RenderOptions& options, const InputReport& report) {
  nlohmann::ordered_json input = {{"file", options.input}, {"read", report.color}};
  if (!options.depth.empty()) input["depth"] = {{"file", options.depth}, {"read", report.depth}};
  return input;
}

// PNG outputs are `encoded` when given (an 8-bit input's result, encoded back as it was decoded),
// else the result tone-mapped.
bool write_outputs(const RenderOptions& options, const Image& result, const DisplayImage* encoded, std::string* error) {
  for (const auto& path : options.outputs) {
    bool ok = ends_with(path, ".png")
                  ? write_png(path, encoded ? *encoded : tonemap_to_srgb8(result, options.tone), error)
                  : write_exr(path, result, options.float_exr ? ExrPixelType::Float : ExrPixelType::Half, error);
    if (!ok) return false;
  }
  return true;
}

nlohmann::ordered_json report_json(const std::string& renderer, const pfx_frame& frame,
                                   const host::FrameReport& report, const ImageStats& stats,
                                   const std::vector<std::string>& outputs, const nlohmann::ordered_json& input) {
  nlohmann::ordered_json root;
  root["renderer"] = renderer;
  if (!input.is_null()) root["input"] = input;
  root["lights"] = frame.light_count;
  root["effects"] = report.effects_run;
  root["effects_skipped"] = report.effects_skipped;
  root["passes"] = nlohmann::ordered_json::array();
  for (const auto& pass : report.passes)
    root["passes"].push_back({{"effect", pass.effect}, {"pass", pass.pass}, {"ms", pass.ms}});
  root["total_ms"] = report.times.total_ms;
  root["timing"] = report.timing;
  root["peak_target_bytes"] = report.peak_target_bytes;
  root["unpooled_target_bytes"] = report.unpooled_target_bytes;
  root["output"] = {{"width", stats.width}, {"height", stats.height}, {"min", stats.min}, {"max", stats.max},
                    {"mean", stats.mean}, {"nonfinite", stats.nonfinite}};
  root["files"] = outputs;
  for (const auto& [effect, members] : report.effect_reports) {
    // An effect's figures are JSON members without braces; a malformed report is shown as text.
    auto parsed = nlohmann::ordered_json::parse("{" + members + "}", nullptr, false);
    root["effect_reports"][effect] = parsed.is_discarded() ? nlohmann::ordered_json(members) : parsed;
  }
  return root;
}

// An image's colour (and depth) as the frame the effects see, through `camera`.
pfx_frame image_frame(const Image& input, const CameraOptions& camera) {
  pfx_frame frame{};
  frame.struct_size = sizeof frame;
  frame.width = static_cast<uint32_t>(input.width);
  frame.height = static_cast<uint32_t>(input.height);
  frame.inputs = PFX_INPUT_COLOR;
  if (input.has_depth()) frame.inputs |= PFX_INPUT_DEPTH;
  frame.depth_encoding = input.has_depth() ? PFX_DEPTH_LINEAR : PFX_DEPTH_NONE;
  frame.camera = make_camera(camera, input.width, input.height);
  frame.light_struct_size = sizeof(pfx_light);
  return frame;
}

// The input's textures: uploaded from the image, or display's decoded colour.
host::FrameTextures upload_image(const Image& input, const DisplayInput* display) {
  host::FrameTextures textures;
  if (display) {
    textures.color = display->color();
    return textures;
  }
  textures.color = upload_color_texture(input);
  textures.depth = upload_depth_texture(input);
  return textures;
}

void release_textures(const host::FrameTextures& textures, const DisplayInput* display) {
  if (display) return;  // display's own
  delete_texture(textures.color);
  delete_texture(textures.depth);
}

// Runs the chain over one frame and reads the result back: into display's output texture, and
// then also *encoded, for an 8-bit input; else into a texture of its own.
bool render_to_image(host::Chain& chain, const pfx_frame& frame, const host::FrameTextures& textures,
                     DisplayInput* display, Transfer transfer, Image* result, DisplayImage* encoded,
                     std::string* error) {
  const int width = static_cast<int>(frame.width), height = static_cast<int>(frame.height);
  uint32_t output = display ? display->output() : create_color_texture(width, height);
  const bool rendered = chain.render(frame, textures, output, error);
  // The pixels are read back next anyway, so waiting for the frame's times costs nothing.
  if (rendered) chain.wait_for_timings();
  if (rendered) *result = download_color_texture(output, width, height);
  if (rendered && display) *encoded = display->encode_output(transfer);
  if (!display) delete_texture(output);
  return rendered;
}

// One frame of a sequence: the frame's input (and depth) through the chain, which keeps its
// plugins, programs and targets from the frame before, to the frame's outputs.
bool render_sequence_frame(const RenderOptions& effective, const FrameFiles& files, host::Chain& chain,
                           DisplayInput* display, const std::string& renderer, nlohmann::ordered_json* report,
                           std::string* error) {
  RenderOptions options = effective;
  options.input = files.input;
  options.depth = files.depth;
  options.outputs = files.outputs;
  Image input, result;
  DisplayImage encoded;
  InputReport input_report;
  if (!load_input(options, display, &input, &input_report, error)) return false;
  const pfx_frame frame = image_frame(input, effective.camera);
  const host::FrameTextures textures = upload_image(input, display);
  const bool rendered =
      render_to_image(chain, frame, textures, display, input_transfer(options), &result, &encoded, error);
  release_textures(textures, display);
  if (!rendered || !write_outputs(options, result, display ? &encoded : nullptr, error)) return false;
  *report = report_json(renderer, frame, chain.report(), compute_image_stats(result), options.outputs,
                        input_json(options, input_report));
  return true;
}

int run(const RenderOptions& options) {
  std::unique_ptr<HeadlessContext> context;
  std::string message;
  if (!options.list) {
    context = HeadlessContext::create(&message);
    if (!context) return error_exit(kInternal, message);
  }
  host::PluginRegistry registry([](const char* name) { return HeadlessContext::get_proc_address(nullptr, name); },
                                host::stderr_log_sink(options.verbose ? PFX_LOG_DEBUG : PFX_LOG_INFO),
                                "pfx-render " PFX_VERSION);
  std::vector<std::string> load_errors = load_plugins(registry, options.plugin_dirs);
  if (options.list) {
    std::fputs((options.json ? plugin_listing_json(registry, load_errors) + "\n"
                             : plugin_listing_text(registry, load_errors)).c_str(), stdout);
    return kOk;
  }
  for (const auto& error : load_errors) std::fprintf(stderr, "pfx-render: warning: plugin not loaded: %s\n", error.c_str());

  // A preset gives the chain, the values, the camera and the display settings; the command line
  // overrides each of them.
  Preset preset;
  if (!options.preset.empty() && !read_preset(options.preset, &preset, &message)) return error_exit(kBadInput, message);
  RenderOptions effective = options;
  if (preset.exposure_ev && !options.exposure_given) effective.tone.exposure_ev = *preset.exposure_ev;
  if (preset.tone && !options.tone_given) effective.tone.curve = *preset.tone;
  effective.camera = CameraOptions{};
  apply_preset_camera(preset.camera, &effective.camera);
  apply_camera_keys(options.camera, options.camera_keys, &effective.camera);

  // An 8-bit input holds nothing above 1.0: effects start from their display-referred defaults
  // (bloom's threshold below 1), unless --defaults says otherwise.
  host::ParamStore params(uses_display_defaults(options) ? host::DefaultSet::DISPLAY_REFERRED
                                                         : host::DefaultSet::SCENE_REFERRED);
  for (const auto& effect : registry.effects()) params.add_effect(effect.desc);
  host::Chain chain(registry, params);
  host::Timing timing = host::Timing::OFF;
  parse_timing(options.timing, context->renderer(), &timing);  // the name was checked with the options
  chain.set_timing(timing);
  std::vector<PresetEffect> effects;
  if (options.chain_given || !preset.chain)
    for (const auto& id : options.chain_given ? options.chain : default_chain(registry)) effects.push_back({id, true});
  else
    effects = *preset.chain;
  for (const auto& effect : effects) {
    if (!chain.add(effect.id, &message)) return error_exit(kEffectError, message);
    chain.set_enabled(chain.size() - 1, effect.enabled);
  }

  // Values after the chain: "bloom#2" exists once the chain holds a second bloom.
  if (!preset.parameters_json.empty() && !params.from_json(preset.parameters_json, &message))
    return error_exit(kBadInput, options.preset + ": parameters: " + message);
  for (const auto& assignment : options.sets) {
    std::string note;
    if (!params.set_assignment(assignment, &message, &note)) return error_exit(kUsage, "--set " + message);
    if (!note.empty()) std::fprintf(stderr, "pfx-render: warning: --set %s: %s\n", assignment.c_str(), note.c_str());
  }

  std::unique_ptr<DisplayInput> display;
  if (has_display_input(options)) {
    display = DisplayInput::create(&message);
    if (!display) return error_exit(kInternal, message);
    if (preset.exposure_ev || preset.tone)
      std::fprintf(stderr, "pfx-render: note: %s: the display settings do not apply to an 8-bit input\n",
                   options.preset.c_str());
  }

  if (options.sequence.given) {
    return run_sequence(options, [&](const FrameFiles& files, nlohmann::ordered_json* report, std::string* error) {
      return render_sequence_frame(effective, files, chain, display.get(), context->renderer(), report, error);
    });
  }

  // The frame: the demo scene's G-buffer, or an image's colour (and depth).
  Scene scene;
  std::unique_ptr<SceneRenderer> scene_renderer;
  Image input;
  InputReport input_report;
  pfx_frame frame{};
  host::FrameTextures textures;
  if (options.demo || !options.scene.empty()) {
    if (options.demo) {
      scene = make_demo_scene({options.extra_lights, options.seed});
    } else {
      pfx::import::SceneImportOptions import_options;
      import_options.seed = options.seed;
      if (options.lights_given) import_options.lights = options.extra_lights;
      std::vector<std::string> warnings;
      if (!pfx::import::load_scene_from_model(registry, options.scene, import_options, &scene, &warnings, &message))
        return error_exit(kBadInput, message);
      for (const auto& warning : warnings) std::fprintf(stderr, "pfx-render: warning: %s\n", warning.c_str());
    }
    apply_preset_camera(preset.camera, &scene.camera);
    apply_camera_keys(options.camera, options.camera_keys, &scene.camera);
    if (!validate_scene(scene, &message)) return error_exit(kUsage, "--camera: " + message);
    scene_renderer = SceneRenderer::create(scene, &message);
    if (!scene_renderer) return error_exit(kInternal, message);
    scene_renderer->render(scene.camera, options.width, options.height);
    frame = make_scene_frame(scene, scene.camera, options.width, options.height);
    textures = scene_renderer->textures();
  } else {
    if (!load_input(options, display.get(), &input, &input_report, &message)) return error_exit(kBadInput, message);
    frame = image_frame(input, effective.camera);
    textures = upload_image(input, display.get());
  }

  Image result;
  DisplayImage encoded;
  const bool rendered = render_to_image(chain, frame, textures, display.get(), input_transfer(options), &result,
                                        &encoded, &message);
  if (!scene_renderer) release_textures(textures, display.get());
  if (!rendered) return error_exit(kEffectError, message);

  if (!write_outputs(effective, result, display ? &encoded : nullptr, &message)) return error_exit(kInternal, message);
  const host::FrameReport& report = chain.report();
  if (options.json) {
    const nlohmann::ordered_json input_read = options.input.empty() ? nlohmann::ordered_json() : input_json(options, input_report);
    std::puts(report_json(context->renderer(), frame, report, compute_image_stats(result), options.outputs, input_read)
                  .dump(2)
                  .c_str());
  } else {
    if (!options.input.empty()) {
      std::fprintf(stderr, "input: %s: %s\n", options.input.c_str(), input_report.color.c_str());
      if (!options.depth.empty())
        std::fprintf(stderr, "depth: %s: %s\n", options.depth.c_str(), input_report.depth.c_str());
    }
    std::fprintf(stderr, "renderer: %s (timing: %s)\n", context->renderer().c_str(), report.timing.c_str());
    for (const auto& pass : report.passes)
      std::fprintf(stderr, "  %-12s %-16s %8.3f ms\n", pass.effect.c_str(), pass.pass.c_str(), pass.ms);
    std::fprintf(stderr, "  total %.3f ms over %zu passes; peak target memory %llu bytes\n", report.times.total_ms,
                 report.passes.size(), static_cast<unsigned long long>(report.peak_target_bytes));
    if (report.passes.empty()) std::fprintf(stderr, "  no effect ran: the output is the input\n");
  }
  return kOk;
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
  try {
    return run(options);
  } catch (const std::exception& e) {
    return error_exit(kInternal, std::string("internal error: ") + e.what());
  }
}
