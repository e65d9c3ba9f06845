// pfx-view's command line, parsed into plain data so it can be tested on its own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "camera_options.hpp"
#include "tonemap.hpp"

namespace pfx::app {

enum class ViewInput { DemoScene, ModelScene, DemoImage, Image };

struct ViewOptions {
  bool help = false;
  ViewInput input = ViewInput::DemoScene;  // --demo (the default), --scene, --demo-image, --input
  std::string input_path, depth_path;       // --input IMG.exr [--depth DEPTH.exr]
  std::string layer;                        // --layer NAME: the part or layer of --input to read
  std::string scene_path;                   // --scene FILE.obj
  // --lights N: with --demo N more lights, with --scene N lights instead of the demo's 400.
  bool lights_given = false;
  int extra_lights = 0;
  uint64_t seed = 1;                        // --seed S, --demo and --scene
  // The frame size (--size). Without it the frame follows the window's size (an image keeps its own).
  bool size_given = false;
  int width = 0, height = 0;
  bool window_given = false;
  int window_width = 1280, window_height = 720;  // --window WxH (default: --size, else 1280x720)
  CameraOptions camera;
  std::vector<std::string> camera_keys;  // the keys --camera gave
  std::vector<std::string> plugin_dirs;
  bool chain_given = false;
  std::vector<std::string> chain;
  std::vector<std::string> sets;
  std::string preset;       // --preset FILE: applied at start; also where "save preset" writes by default
  std::string save_preset;  // --save-preset FILE: written when the viewer exits
  ToneMapSettings tone;
  bool exposure_given = false, tone_given = false;
  long long frames = 0;        // --frames N: render N frames, write the screenshots, exit; 0: interactive
  std::string screenshot;      // --screenshot FILE.png: the frame (and FILE.exr beside it)
  std::string window_shot;     // --window-shot FILE.png: the whole window, panels included
  std::string shots_dir = ".";  // --shots DIR: where F12 writes
  bool watch = true;            // --no-watch turns hot reload off
  bool hide_panels = false;     // --hide-panels: start with the panels hidden (Tab shows them)
  bool verbose = false;
  // --attach FILE: the live control panel of a chain injected into an application (pfx-inject
  // --panel): no picture of its own; every change is written to FILE, the preset the injected
  // library watches. --timings FILE: where that library writes its per-pass times.
  std::string attach, timings;
  // --edit N:KEY=VALUE (scripted, with --attach and --frames): at panel frame N, set KEY as its
  // widget would.
  struct Edit {
    long long frame = 0;
    std::string assignment;
  };
  std::vector<Edit> edits;
};

// Parses argv (without argv[0]). False with *error for a usage error (exit code 2).
bool parse_view_options(const std::vector<std::string>& args, ViewOptions* out, std::string* error);
std::string view_usage();

}  // namespace pfx::app
