// pfx-render's command line, parsed into plain data so it can be tested (and fuzzed) on its own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "camera_options.hpp"
#include "display_transfer.hpp"
#include "sequence_options.hpp"
#include "tonemap.hpp"

namespace pfx::app {

struct RenderOptions {
  bool help = false;
  bool list = false;
  bool json = false;
  bool demo = false;                    // --demo: the built-in 3D scene through its G-buffer
  bool demo_image = false;              // --demo-image: the procedural HDR image (colour + depth only)
  int extra_lights = 0;                 // --lights N, --demo only
  uint64_t seed = 1;                    // --seed S, --demo only
  bool lights_given = false, seed_given = false;
  std::string input, depth;             // --input IMG.exr|IMG.png [--depth DEPTH.exr]
  std::string layer;                    // --layer NAME: the part or layer of --input to read
  std::string scene;                    // --scene FILE.obj: an imported model, lit and framed
  int width = 1280, height = 720;       // --size, --demo and --demo-image only
  bool size_given = false;
  CameraOptions camera;
  std::vector<std::string> camera_keys;  // the keys --camera gave ("fovy", "near", "far")
  std::vector<std::string> plugin_dirs;  // --plugins, repeatable
  bool chain_given = false;
  std::vector<std::string> chain;        // --chain a,b,c (empty list: no effect)
  std::vector<std::string> sets;         // --set effect.param=value, repeatable
  std::vector<std::string> outputs;      // --out FILE.exr|FILE.png, repeatable
  bool float_exr = false;
  ToneMapSettings tone;
  bool exposure_given = false, tone_given = false;
  std::string preset;                    // --preset FILE (pfx-view saves them)
  bool strict = false;                   // --strict: a preset that does not apply whole is an error
  std::string transfer = "srgb";         // --transfer srgb|linear: how an 8-bit --input is decoded
  bool transfer_given = false;
  std::string defaults;                  // --defaults scene|display; empty: display for an 8-bit input
  long long max_input_pixels = 1LL << 26;  // --max-input-pixels: larger EXR inputs are refused unread
  std::string timing = "auto";           // auto | gpu | finish | off
  bool verbose = false;
  SequenceOptions sequence;              // --frames, --overwrite, --report (docs/farm.md)
};

// Parses argv (without argv[0]). False with *error for a usage error (exit code 2).
bool parse_render_options(const std::vector<std::string>& args, RenderOptions* out, std::string* error);
// Whether --input is an 8-bit display-referred frame (a PNG), which --transfer decodes.
bool has_display_input(const RenderOptions& options);
// Whether parameters start from their display-referred defaults: --defaults, else an 8-bit input.
bool uses_display_defaults(const RenderOptions& options);
// How an 8-bit input is decoded and its PNG outputs encoded back: --transfer.
Transfer input_transfer(const RenderOptions& options);
std::string render_usage();

}  // namespace pfx::app
