#include "view_options.hpp"

#include <cstdlib>

#include "arg_reader.hpp"
#include "cli_text.hpp"

namespace pfx::app {

std::string view_usage() {
  return
      "usage: pfx-view [--plugins DIR]... [--demo [--lights N] [--seed S] | --demo-image\n"
      "                | --scene FILE.obj [--lights N] [--seed S] | --input IMG.exr [--layer NAME] [--depth DEPTH.exr]\n"
      "                | --input IMG.png]\n"
      "                [--size WxH] [--window WxH]\n"
      "                [--camera fovy=45,near=0.1,far=1000] [--chain a,b,...] [--preset FILE]\n"
      "                [--set effect.param=value]... [--exposure EV] [--tone NAME] [--save-preset FILE]\n"
      "                [--hide-panels] [--no-watch] [--shots DIR]\n"
      "                [--frames N [--screenshot FILE.png] [--window-shot FILE.png]]\n"
      "\n"
      "Shows a scene or an image through a chain of pfx effects in a window (GL 4.5 core, GLFW), with\n"
      "panels made from the plugins' parameter descriptions, per-pass timings and hot reload of\n"
      "rebuilt plugins. docs/viewer.md has the controls.\n"
      "\n"
      "input\n"
      "  --demo               the built-in 3D scene (the default): floor, boxes, spheres, emissive\n"
      "                       objects and 400 point lights; effects get the whole G-buffer and the lights\n"
      "  --lights N           with --demo: N more lights at random inside the scene (default 0)\n"
      "  --seed S             with --demo or --scene: the seed of every random choice (default 1)\n"
      "  --scene FILE.obj     a model imported through the importer plugins, textured and lit by a\n"
      "                       rig scaled to it (400 point lights around it: --lights N for N), as\n"
      "                       pfx-render --scene\n"
      "  --demo-image         the procedural HDR image of pfx-render --demo-image (colour and depth)\n"
      "  --input IMG.exr      an OpenEXR image, read as pfx-render --input reads it: R, G, B (a missing\n"
      "                       one is 0) and A (else 1); or Y as grey (Y, RY, BY converted to RGB); or\n"
      "                       its only channel as grey; the only layer with colour when none is plain.\n"
      "                       A Z channel is linear depth (m). The panel says what was read\n"
      "  --input IMG.png      an 8-bit picture (a photograph, a video frame), kept 8-bit as pfx-render\n"
      "                       keeps it: FX effects read and write its sRGB codes, others see linear\n"
      "                       light; shown and saved as pfx-render writes its PNG (exposure and tone\n"
      "                       do not apply); effects start from their display-referred defaults\n"
      "  --layer NAME         with --input: read the part or layer NAME (e.g. diffuse for diffuse.R)\n"
      "  --depth DEPTH.exr    linear depth (m) from another EXR: its Z channel, else a 'depth' channel\n"
      "                       or the Z of a layer, else R, else Y, else its only channel\n"
      "  --size WxH           the frame size; default: the window's size (an image keeps its own)\n"
      "  --window WxH         the window's first size (default: --size, else 1280x720)\n"
      "  --camera K=V,...     lens: fovy (degrees, 45), near (m, 0.1), far (m, 1000, or inf)\n"
      "\n"
      "effects\n"
      "  --plugins DIR        load plugins from DIR (repeatable); default: the plugins folder next to\n"
      "                       this program's folder; PFX_PLUGIN_PATH (':'-separated) adds more\n"
      "  --chain a,b,...      the effects, in order (default: every loaded effect, as pfx-render); an\n"
      "                       effect may appear more than once, each instance with its own values\n"
      "  --set E.P=V          set parameter P of effect E (repeatable); E#N is the N-th instance of E\n"
      "                       in the chain (bloom#2.strength=0.3), plain E is E#1\n"
      "  --preset FILE        start from a preset (chain, values, camera, display); \"Save preset\"\n"
      "                       writes back to it. --chain, --set, --camera, --exposure, --tone override it\n"
      "  --save-preset FILE   write the look as a preset when the viewer exits (and make FILE where\n"
      "                       \"save preset\" writes)\n"
      "  --no-watch           do not reload plugins whose files change\n"
      "\n"
      "display\n"
      "  --hide-panels        start with the panels hidden (Tab shows and hides them)\n"
      "  --exposure EV        exposure before the tone curve (default 0)\n"
      "  --tone NAME          tone curve: linear (default), reinhard, aces\n"
      "\n"
      "scripted use (tests, documentation)\n"
      "  --frames N           render N frames, 60 a second at most (the effects' clock runs at 60 a\n"
      "                       second), write the files below, exit\n"
      "  --edit N:E.P=V       at frame N (1 is the first) set E.P as its widget would (repeatable)\n"
      "  --screenshot FILE.png  the last frame as pfx-render would write it: FILE.png (tone-mapped;\n"
      "                       from an 8-bit picture, its codes) and FILE.exr (half, scene-linear)\n"
      "  --window-shot FILE.png the whole window, panels included, as shown\n"
      "  --shots DIR          where F12 (or SIGUSR1) writes pfx-view-NNNN.exr/.png/.json (default .)\n"
      "  -v, --verbose        also print debug messages, the passes of each new frame plan and each\n"
      "                       effect's report when it changes\n"
      "\n"
      "live control panel of an application's chain (pfx-inject --panel starts it so)\n"
      "  --attach FILE        no picture: the chain and parameter panels edit FILE, the preset the\n"
      "                       injected library watches (values start at the display-referred\n"
      "                       defaults); --preset names the file \"save\" and \"load\" use\n"
      "  --timings FILE       the per-pass times the injected library writes, shown in a panel\n"
      "\n"
      "signals: SIGUSR1 takes a screenshot as F12 does; SIGINT and SIGTERM close the window cleanly.\n"
      "exit codes: 0 ok, 1 internal error (no window or no OpenGL 4.5 context), 2 usage, 3 bad input\n"
      "            file, 4 plugin or effect error (at start, or any frame of a scripted run)\n";
}

namespace {

// What the arguments gave: the options, and what the checks of options that go together need
// besides.
struct Parsed {
  ViewOptions options;
  int inputs_given = 0;
  bool seed_given = false;
};

// Options without a value that set a switch.
struct SwitchOption {
  const char* name;
  bool ViewOptions::*field;
  bool value;
};
const SwitchOption kSwitchOptions[] = {
    {"-h", &ViewOptions::help, true},           {"--help", &ViewOptions::help, true},
    {"-v", &ViewOptions::verbose, true},        {"--verbose", &ViewOptions::verbose, true},
    {"--no-watch", &ViewOptions::watch, false}, {"--hide-panels", &ViewOptions::hide_panels, true}};

// Where the picture comes from; the inputs read from a file take its name as their value.
struct InputOption {
  const char* name;
  ViewInput input;
  std::string ViewOptions::*path;  // null for the built-in ones
};
const InputOption kInputOptions[] = {{"--demo", ViewInput::DemoScene, nullptr},
                                     {"--demo-image", ViewInput::DemoImage, nullptr},
                                     {"--input", ViewInput::Image, &ViewOptions::input_path},
                                     {"--scene", ViewInput::ModelScene, &ViewOptions::scene_path}};

// Options whose value is kept as given: a file, a folder, a name. The screenshots are PNG files.
struct TextOption {
  const char* name;
  std::string ViewOptions::*field;
  bool png;
};
const TextOption kTextOptions[] = {
    {"--depth", &ViewOptions::depth_path, false},     {"--layer", &ViewOptions::layer, false},
    {"--preset", &ViewOptions::preset, false},        {"--save-preset", &ViewOptions::save_preset, false},
    {"--screenshot", &ViewOptions::screenshot, true}, {"--window-shot", &ViewOptions::window_shot, true},
    {"--shots", &ViewOptions::shots_dir, false},      {"--attach", &ViewOptions::attach, false},
    {"--timings", &ViewOptions::timings, false}};

// Repeatable options, each value appended in order.
struct ListOption {
  const char* name;
  std::vector<std::string> ViewOptions::*field;
};
const ListOption kListOptions[] = {{"--plugins", &ViewOptions::plugin_dirs}, {"--set", &ViewOptions::sets}};

// --edit N:E.P=V.
bool read_edit(const std::string& text, Parsed* parsed, std::string* error) {
  const size_t colon = text.find(':');
  ViewOptions::Edit edit;
  if (colon == std::string::npos || !parse_count(text.substr(0, colon), &edit.frame) || edit.frame < 1 ||
      text.find('=', colon) == std::string::npos) {
    *error = "--edit " + text + ": expected FRAME:EFFECT.PARAM=VALUE";
    return false;
  }
  edit.assignment = text.substr(colon + 1);
  parsed->options.edits.push_back(edit);
  return true;
}

bool read_frames(const std::string& text, Parsed* parsed, std::string* error) {
  long long& frames = parsed->options.frames;
  if (parse_count(text, &frames) && frames >= 1 && frames <= 1000000) return true;
  *error = "--frames " + text + ": expected a whole number from 1 to 1000000";
  return false;
}

// Options whose value is parsed: each keeps what it read, or returns false with *error.
struct ValueOption {
  const char* name;
  bool (*read)(const std::string& text, Parsed* parsed, std::string* error);
};
const ValueOption kValueOptions[] = {
    {"--chain",
     [](const std::string& text, Parsed* parsed, std::string*) {
       parsed->options.chain_given = true;
       parsed->options.chain = split_list(text);
       return true;
     }},
    {"--size",
     [](const std::string& text, Parsed* parsed, std::string* error) {
       ViewOptions& o = parsed->options;
       if (!parse_frame_size("--size", text, &o.width, &o.height, error)) return false;
       o.size_given = true;
       return true;
     }},
    {"--window",
     [](const std::string& text, Parsed* parsed, std::string* error) {
       ViewOptions& o = parsed->options;
       if (!parse_frame_size("--window", text, &o.window_width, &o.window_height, error)) return false;
       o.window_given = true;
       return true;
     }},
    {"--camera",
     [](const std::string& text, Parsed* parsed, std::string* error) {
       if (!parse_camera_options(text, &parsed->options.camera, error)) return false;
       for (const auto& key : option_keys(text)) parsed->options.camera_keys.push_back(key);
       return true;
     }},
    {"--lights",
     [](const std::string& text, Parsed* parsed, std::string* error) {
       if (!parse_light_count(text, &parsed->options.extra_lights, error)) return false;
       parsed->options.lights_given = true;
       return true;
     }},
    {"--seed",
     [](const std::string& text, Parsed* parsed, std::string* error) {
       if (!parse_seed(text, &parsed->options.seed, error)) return false;
       parsed->seed_given = true;
       return true;
     }},
    {"--edit", read_edit},
    {"--frames", read_frames},
    {"--exposure",
     [](const std::string& text, Parsed* parsed, std::string* error) {
       if (!parse_exposure(text, &parsed->options.tone.exposure_ev, error)) return false;
       parsed->options.exposure_given = true;
       return true;
     }},
    {"--tone", [](const std::string& text, Parsed* parsed, std::string* error) {
       if (!parse_tone_curve(text, &parsed->options.tone.curve, error)) return false;
       parsed->options.tone_given = true;
       return true;
     }}};

// The argument in hand, looked up in the tables above: false with the reader's error when it is
// unknown or its value is missing or wrong.
bool read_option(ArgReader& args, Parsed* parsed, std::string* error) {
  const std::string& arg = args.arg();
  ViewOptions& options = parsed->options;
  for (const SwitchOption& option : kSwitchOptions)
    if (arg == option.name) return options.*option.field = option.value, true;
  for (const InputOption& option : kInputOptions)
    if (arg == option.name) {
      if (option.path && !args.value(&(options.*option.path))) return false;
      options.input = option.input;
      ++parsed->inputs_given;
      return true;
    }
  for (const TextOption& option : kTextOptions)
    if (arg == option.name) {
      std::string& value = options.*option.field;
      if (!args.value(&value)) return false;
      if (option.png && !ends_with(value, ".png"))
        return args.fail(arg + " " + value + ": the file name must end in .png");
      return true;
    }
  for (const ListOption& option : kListOptions)
    if (arg == option.name) return args.value(&(options.*option.field));
  for (const ValueOption& option : kValueOptions)
    if (arg == option.name) {
      std::string text;
      return args.value(&text) && option.read(text, parsed, error);
    }
  return args.unknown();
}

// What is wrong with the options together: one that needs another, or two that exclude each
// other; "" when nothing is.
std::string conflict(const Parsed& parsed) {
  const ViewOptions& options = parsed.options;
  const bool image = options.input == ViewInput::Image;
  if (parsed.inputs_given > 1) return "give at most one of --demo, --demo-image, --scene FILE.obj or --input IMG";
  if (!options.depth_path.empty() && !image) return "--depth goes with --input";
  if (!options.layer.empty() && !image) return "--layer goes with --input";
  if (options.size_given && image) return "--size applies to --demo and --demo-image (an input image has its own size)";
  if ((options.lights_given || parsed.seed_given) && options.input != ViewInput::DemoScene &&
      options.input != ViewInput::ModelScene)
    return "--lights and --seed go with --demo or --scene";
  if ((!options.screenshot.empty() || !options.window_shot.empty()) && options.frames == 0)
    return "--screenshot and --window-shot go with --frames N";
  if (!options.attach.empty() && (parsed.inputs_given || options.size_given || !options.screenshot.empty()))
    return "--attach shows no picture: leave out the input, --size and --screenshot";
  if (!options.timings.empty() && options.attach.empty()) return "--timings goes with --attach";
  if (!options.edits.empty() && options.frames == 0) return "--edit goes with --frames N";
  return "";
}

}  // namespace

bool parse_view_options(const std::vector<std::string>& list, ViewOptions* out, std::string* error) {
  Parsed parsed;
  ArgReader args(list, error);
  while (args.next())
    if (!read_option(args, &parsed, error)) return false;
  ViewOptions& options = parsed.options;
  if (!options.help) {
    if (const std::string problem = conflict(parsed); !problem.empty()) return args.fail(problem);
    // The window opens at the frame's size unless told otherwise.
    if (options.size_given && !options.window_given)
      options.window_width = options.width, options.window_height = options.height;
  }
  *out = options;
  return true;
}

}  // namespace pfx::app
