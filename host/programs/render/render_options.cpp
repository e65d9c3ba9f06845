#include "render_options.hpp"

#include "arg_reader.hpp"
#include "cli_text.hpp"
#include "display_transfer.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace pfx::app {

namespace {

// The options that only switch something on. False when `arg` is none of them.
bool take_switch(const std::string& arg, RenderOptions* options) {
  if (arg == "-h" || arg == "--help") options->help = true;
  else if (arg == "--list") options->list = true;
  else if (arg == "--json") options->json = true;
  else if (arg == "--demo") options->demo = true;
  else if (arg == "--demo-image") options->demo_image = true;
  else if (arg == "--float") options->float_exr = true;
  else if (arg == "-v" || arg == "--verbose") options->verbose = true;
  else if (arg == "--strict") options->strict = true;
  else return false;
  return true;
}

// The options of the usage's "input" section that take a value: what the chain runs over and how
// it is read. Returns false on a usage error; *taken says whether `args.arg()` was one of them.
bool parse_input_option(ArgReader& args, RenderOptions* options, bool* taken, std::string* error) {
  const std::string& arg = args.arg();
  std::string text;
  *taken = true;
  if (arg == "--input") return args.value(&options->input);
  if (arg == "--scene") return args.value(&options->scene);
  if (arg == "--depth") return args.value(&options->depth);
  if (arg == "--layer") return args.value(&options->layer);
  if (arg == "--transfer") {
    if (!args.value(&options->transfer)) return false;
    Transfer transfer;
    std::string why;
    if (!parse_transfer(options->transfer, &transfer, &why)) return args.fail("--transfer: " + why);
    options->transfer_given = true;
  } else if (arg == "--size") {
    if (!args.value(&text)) return false;
    if (!parse_frame_size("--size", text, &options->width, &options->height, error)) return false;
    options->size_given = true;
  } else if (arg == "--camera") {
    if (!args.value(&text)) return false;
    if (!parse_camera_options(text, &options->camera, error)) return false;
    for (const auto& key : option_keys(text)) options->camera_keys.push_back(key);
  } else if (arg == "--lights") {
    if (!args.value(&text) || !parse_light_count(text, &options->extra_lights, error)) return false;
    options->lights_given = true;
  } else if (arg == "--seed") {
    if (!args.value(&text) || !parse_seed(text, &options->seed, error)) return false;
    options->seed_given = true;
  } else if (arg == "--max-input-pixels") {
    if (!args.value(&text)) return false;
    char* end = nullptr;
    options->max_input_pixels = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end || options->max_input_pixels < 1 || options->max_input_pixels > (1LL << 40))
      return args.fail("--max-input-pixels " + text + ": expected a whole number from 1 to 2^40");
  } else {
    *taken = false;
  }
  return true;
}

// The options of the "effects" and "output" sections that take a value: which effects run with
// which values, and what is written. Returns and sets *taken as parse_input_option does.
bool parse_chain_or_output_option(ArgReader& args, RenderOptions* options, bool* taken, std::string* error) {
  const std::string& arg = args.arg();
  std::string text;
  *taken = true;
  if (arg == "--plugins") return args.value(&options->plugin_dirs);
  if (arg == "--set") return args.value(&options->sets);
  if (arg == "--preset") return args.value(&options->preset);
  if (arg == "--defaults") {
    if (!args.value(&options->defaults)) return false;
    if (options->defaults != "scene" && options->defaults != "display")
      return args.fail("--defaults " + options->defaults + ": expected scene or display");
  } else if (arg == "--chain") {
    if (!args.value(&text)) return false;
    options->chain_given = true;
    // "none", as every other host takes it: no effect (the frame as read, converted for --out).
    options->chain = text == "none" ? std::vector<std::string>{} : split_list(text);
  } else if (arg == "--out") {
    if (!args.value(&text)) return false;
    if (!ends_with(text, ".exr") && !ends_with(text, ".png"))
      return args.fail("--out " + text + ": the file name must end in .exr or .png");
    options->outputs.push_back(text);
  } else if (arg == "--exposure") {
    if (!args.value(&text) || !parse_exposure(text, &options->tone.exposure_ev, error)) return false;
    options->exposure_given = true;
  } else if (arg == "--tone") {
    if (!args.value(&text)) return false;
    if (!parse_tone_curve(text, &options->tone.curve, error)) return false;
    options->tone_given = true;
  } else if (arg == "--timing") {
    if (!args.value(&options->timing)) return false;
    if (options->timing != "auto" && options->timing != "gpu" && options->timing != "finish" &&
        options->timing != "off")
      return args.fail("--timing " + options->timing + ": expected auto, gpu, finish or off");
  } else {
    *taken = false;
  }
  return true;
}

// What no single option can check: which options go together. False, through args.fail, when
// the command line as a whole asks for something pfx-render cannot do.
bool check_option_combination(const RenderOptions& options, ArgReader& args) {
  if (int(options.demo) + int(options.demo_image) + int(!options.input.empty()) + int(!options.scene.empty()) != 1)
    return args.fail("give exactly one of --demo, --demo-image, --scene FILE.obj or --input IMG.exr");
  if (!options.depth.empty() && options.input.empty()) return args.fail("--depth goes with --input");
  if (!options.layer.empty() && options.input.empty()) return args.fail("--layer goes with --input");
  if (has_display_input(options)) {
    if (!options.depth.empty() || !options.layer.empty())
      return args.fail("--depth and --layer go with an EXR --input (" + options.input + " is an 8-bit PNG)");
    if (options.exposure_given || options.tone_given)
      return args.fail("--exposure and --tone tone-map an HDR input; the PNG output of an 8-bit --input is "
                       "encoded back as it was decoded (--transfer)");
  } else if (options.transfer_given) {
    return args.fail("--transfer goes with an 8-bit --input (IMG.png)");
  }
  if (options.size_given && !options.input.empty())
    return args.fail("--size applies to --demo and --demo-image (an input image has its own size)");
  if ((options.lights_given || options.seed_given) && !options.demo && options.scene.empty())
    return args.fail("--lights and --seed go with --demo or --scene");
  std::string sequence_error;
  if (!check_sequence_options(options.sequence, options.input, options.depth, options.outputs,
                              options.demo || options.demo_image || !options.scene.empty(), &sequence_error))
    return args.fail(sequence_error);
  if (options.outputs.empty() && !options.json) return args.fail("nothing to do: give --out FILE and/or --json");
  return true;
}

}  // namespace

bool parse_render_options(const std::vector<std::string>& list, RenderOptions* out, std::string* error) {
  RenderOptions options;
  ArgReader args(list, error);
  while (args.next()) {
    if (take_switch(args.arg(), &options)) continue;
    bool taken = false;
    if (!parse_input_option(args, &options, &taken, error)) return false;
    if (!taken && !parse_chain_or_output_option(args, &options, &taken, error)) return false;
    if (!taken && !parse_sequence_option(args, &options.sequence, &taken)) return false;
    if (!taken) return args.unknown();
  }
  // --help and --list need nothing else, and ignore what does not go together.
  if (!options.help && !options.list && !check_option_combination(options, args)) return false;
  *out = options;
  return true;
}

bool has_display_input(const RenderOptions& options) { return is_display_input(options.input); }

bool uses_display_defaults(const RenderOptions& options) {
  return options.defaults.empty() ? has_display_input(options) : options.defaults == "display";
}

Transfer input_transfer(const RenderOptions& options) {
  Transfer transfer = Transfer::SRGB;
  std::string unused;
  parse_transfer(options.transfer, &transfer, &unused);  // checked with the options
  return transfer;
}

}  // namespace pfx::app
