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
      "  --input IMG.png      an 8-bit picture (a photograph, a video frame), decoded to linear light\n"
      "                       with the sRGB curve as pfx-render decodes it; effects start from their\n"
      "                       display-referred defaults, as there\n"
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
      "  --frames N           render N frames, write the files below, exit\n"
      "  --screenshot FILE.png  the last frame as pfx-render would write it: FILE.png (tone-mapped)\n"
      "                       and FILE.exr (half, scene-linear) beside it\n"
      "  --window-shot FILE.png the whole window, panels included, as shown\n"
      "  --shots DIR          where F12 (or SIGUSR1) writes pfx-view-NNNN.exr/.png/.json (default .)\n"
      "  -v, --verbose        also print debug messages\n"
      "\n"
      "live control panel of an application's chain (pfx-inject --panel starts it so)\n"
      "  --attach FILE        no picture: the chain and parameter panels edit FILE, the preset the\n"
      "                       injected library watches (values start at the display-referred\n"
      "                       defaults); --preset names the file \"save\" and \"load\" use\n"
      "  --timings FILE       the per-pass times the injected library writes, shown in a panel\n"
      "  --edit N:E.P=V       scripted (--frames): at frame N set E.P as its widget would (repeatable)\n"
      "\n"
      "signals: SIGUSR1 takes a screenshot as F12 does; SIGINT and SIGTERM close the window cleanly.\n"
      "exit codes: 0 ok, 1 internal error (no window or no OpenGL 4.5 context), 2 usage, 3 bad input\n"
      "            file, 4 plugin or effect error (at start, or any frame of a scripted run)\n";
}

bool parse_view_options(const std::vector<std::string>& list, ViewOptions* out, std::string* error) {
  ViewOptions options;
  int inputs_given = 0;
  bool seed_given = false;
  pfx::app::ArgReader args(list, error);
  while (args.next()) {
    const std::string& arg = args.arg();
    std::string text;
    if (arg == "-h" || arg == "--help") options.help = true;
    else if (arg == "-v" || arg == "--verbose") options.verbose = true;
    else if (arg == "--no-watch") options.watch = false;
    else if (arg == "--hide-panels") options.hide_panels = true;
    else if (arg == "--demo") options.input = ViewInput::DemoScene, ++inputs_given;
    else if (arg == "--demo-image") options.input = ViewInput::DemoImage, ++inputs_given;
    else if (arg == "--input") {
      if (!args.value(&options.input_path)) return false;
      options.input = ViewInput::Image;
      ++inputs_given;
    } else if (arg == "--scene") {
      if (!args.value(&options.scene_path)) return false;
      options.input = ViewInput::ModelScene;
      ++inputs_given;
    } else if (arg == "--depth") { if (!args.value(&options.depth_path)) return false; }
    else if (arg == "--layer") { if (!args.value(&options.layer)) return false; }
    else if (arg == "--preset") { if (!args.value(&options.preset)) return false; }
    else if (arg == "--save-preset") { if (!args.value(&options.save_preset)) return false; }
    else if (arg == "--screenshot") {
      if (!args.value(&options.screenshot)) return false;
      if (!ends_with(options.screenshot, ".png")) return args.fail("--screenshot " + options.screenshot + ": the file name must end in .png");
    } else if (arg == "--window-shot") {
      if (!args.value(&options.window_shot)) return false;
      if (!ends_with(options.window_shot, ".png")) return args.fail("--window-shot " + options.window_shot + ": the file name must end in .png");
    } else if (arg == "--shots") { if (!args.value(&options.shots_dir)) return false; }
    else if (arg == "--plugins") {
      if (!args.value(&options.plugin_dirs)) return false;
    } else if (arg == "--set") {
      if (!args.value(&options.sets)) return false;
    } else if (arg == "--chain") {
      if (!args.value(&text)) return false;
      options.chain_given = true;
      options.chain = split_list(text);
    } else if (arg == "--size") {
      if (!args.value(&text) || !parse_frame_size("--size", text, &options.width, &options.height, error)) return false;
      options.size_given = true;
    } else if (arg == "--window") {
      if (!args.value(&text) || !parse_frame_size("--window", text, &options.window_width, &options.window_height, error))
        return false;
      options.window_given = true;
    } else if (arg == "--camera") {
      if (!args.value(&text) || !parse_camera_options(text, &options.camera, error)) return false;
      for (const auto& key : option_keys(text)) options.camera_keys.push_back(key);
    } else if (arg == "--lights") {
      if (!args.value(&text) || !parse_light_count(text, &options.extra_lights, error)) return false;
      options.lights_given = true;
    } else if (arg == "--seed") {
      if (!args.value(&text) || !parse_seed(text, &options.seed, error)) return false;
      seed_given = true;
    } else if (arg == "--attach") {
      if (!args.value(&options.attach)) return false;
    } else if (arg == "--timings") {
      if (!args.value(&options.timings)) return false;
    } else if (arg == "--edit") {
      std::string text;
      if (!args.value(&text)) return false;
      const size_t colon = text.find(':');
      ViewOptions::Edit edit;
      if (colon == std::string::npos || !parse_count(text.substr(0, colon), &edit.frame) || edit.frame < 1 ||
          text.find('=', colon) == std::string::npos)
        return args.fail("--edit " + text + ": expected FRAME:EFFECT.PARAM=VALUE");
      edit.assignment = text.substr(colon + 1);
      options.edits.push_back(edit);
    } else if (arg == "--frames") {
      if (!args.value(&text)) return false;
      if (!parse_count(text, &options.frames) || options.frames < 1 || options.frames > 1000000)
        return args.fail("--frames " + text + ": expected a whole number from 1 to 1000000");
    } else if (arg == "--exposure") {
      if (!args.value(&text) || !parse_exposure(text, &options.tone.exposure_ev, error)) return false;
      options.exposure_given = true;
    } else if (arg == "--tone") {
      if (!args.value(&text) || !parse_tone_curve(text, &options.tone.curve, error)) return false;
      options.tone_given = true;
    } else {
      return args.unknown();
    }
  }
  if (options.help) {
    *out = options;
    return true;
  }
  if (inputs_given > 1) return args.fail("give at most one of --demo, --demo-image, --scene FILE.obj or --input IMG");
  if (!options.depth_path.empty() && options.input != ViewInput::Image) return args.fail("--depth goes with --input");
  if (!options.layer.empty() && options.input != ViewInput::Image) return args.fail("--layer goes with --input");
  if (options.size_given && options.input == ViewInput::Image)
    return args.fail("--size applies to --demo and --demo-image (an input image has its own size)");
  if ((options.lights_given || seed_given) && options.input != ViewInput::DemoScene &&
      options.input != ViewInput::ModelScene)
    return args.fail("--lights and --seed go with --demo or --scene");
  if (options.size_given && !options.window_given) options.window_width = options.width, options.window_height = options.height;
  if ((!options.screenshot.empty() || !options.window_shot.empty()) && options.frames == 0)
    return args.fail("--screenshot and --window-shot go with --frames N");
  if (!options.attach.empty() && (inputs_given || options.size_given || !options.screenshot.empty()))
    return args.fail("--attach shows no picture: leave out the input, --size and --screenshot");
  if ((!options.timings.empty() || !options.edits.empty()) && options.attach.empty())
    return args.fail("--timings and --edit go with --attach");
  if (!options.edits.empty() && options.frames == 0) return args.fail("--edit goes with --frames N");
  *out = options;
  return true;
}

}  // namespace pfx::app
