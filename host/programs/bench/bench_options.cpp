#include "bench_options.hpp"

#include "arg_reader.hpp"
#include "cli_text.hpp"

#include <cstdio>
#include <cstdlib>

namespace pfx::bench {

std::string bench_usage() {
  return
      "usage: pfx-bench [--plugins DIR]... [--out DIR] [--sizes WxH,...] [--frames N] [--warmup N]\n"
      "                 [--effects a,b,...] [--suite FILE] [--set E.P=V]... [--timing auto|gpu|finish]\n"
      "                 [--input FRAME.exr|.png [--truth TRUTH.exr [--halo-mask MASK.exr]]]... [--layer NAME]\n"
      "                 [--camera ...] [--halo-tolerance T] [--quick] [--no-shift]\n"
      "\n"
      "Measures, in one process and one run, a plain full-screen copy pass at each size (the unit),\n"
      "then every effect at every setting of the suite: median time over --frames frames after\n"
      "--warmup frames, ratio to the copy pass (timed again before each of the row's frames, so load\n"
      "that drifts on a shared machine cancels out), peak target bytes, time per pass, the error\n"
      "against the effect's CPU references where its plugin ships them (pfx/reference.h), relative\n"
      "to the whole frame and to the change the reference makes, and shift invariance: one bright\n"
      "pixel on black moved over 16 positions, the spread of the light added (coefficient of\n"
      "variation) and of the aligned responses (relative RMS).\n"
      "Writes DIR/bench.json, DIR/bench.md (tables) and DIR/error_vs_time.png (gnuplot; only when\n"
      "some effect has an ideal reference or a truth is given: error against time, one curve per\n"
      "effect, mode and size). The input is the built-in demo image at each size, or the --input\n"
      "frames.\n"
      "\n"
      "  --plugins DIR     plugin folder (repeatable; default: the one next to this program's folder)\n"
      "  --out DIR         output folder (default out/bench)\n"
      "  --sizes LIST      frame sizes (default 1280x720,1920x1080)\n"
      "  --frames N        measured frames per row (default 15), --warmup N unmeasured ones first (3)\n"
      "  --effects LIST    only these effects\n"
      "  --suite FILE      rows to run, one per line: EFFECT [param=value ...] ('#' comments);\n"
      "                    default: the built-in suite; loaded effects it does not name run at defaults\n"
      "  --set E.P=V       set parameter P of effect E in every row, before the row's own settings\n"
      "                    (a row runs one instance of its effect: E#1 is E, E#2 does not exist)\n"
      "  --input FRAME.exr measure on this frame (repeatable; replaces --sizes), read as pfx-render\n"
      "                    --input reads it (R, G, B, A; Y; a lone channel as grey; the only layer\n"
      "                    with colour), its Z channel as linear depth (m)\n"
      "  --input FRAME.png an 8-bit frame (sRGB codes, as a video or an application hands one\n"
      "                    over): the chain reads and writes it in 8-bit textures as every host of\n"
      "                    8-bit frames runs it, with the display-referred defaults; errors are of\n"
      "                    the 8-bit result\n"
      "  --layer NAME      read the part or layer NAME of every --input (e.g. diffuse for diffuse.R)\n"
      "  --camera K=V,...  the camera the effects see: fovy (degrees, default 45), near (0.1), far\n"
      "                    (1000 or inf), as pfx-render takes it\n"
      "  --truth FILE.exr  per --input, in order: what every output should ideally be (e.g. a\n"
      "                    lens-sampled render); adds 'error vs truth' (relative RMSE / max) per row,\n"
      "                    which the plot then shows\n"
      "  --halo-mask FILE  per --input, in order (needs --truth): an object (R > 0.5) whose halo is\n"
      "                    measured: how many 1 px rings just outside it have a mean error against the\n"
      "                    truth (largest of R, G, B) above --halo-tolerance (default 0.05)\n"
      "  --timing MODE     auto (default: finish on a software renderer, whose GL timestamps are\n"
      "                    taken when commands are queued; gpu elsewhere), gpu (GL timestamp\n"
      "                    queries, each frame's waited for once it is rendered), finish (glFinish\n"
      "                    + CPU clock around every pass)\n"
      "  --quick           one size (640x360), 5 frames, 2 warm-up: a smoke test under a minute\n"
      "  --no-shift        skip the shift-invariance probe (16 extra frames per row)\n"
      "\n"
      "pfx-bench --import ... measures the OBJ importer against tinyobjloader and assimp instead\n"
      "(no GL; see pfx-bench --import --help).\n"
      "pfx-bench --lights ... measures the tiledlights effect against its light count on a scene of\n"
      "its own (see pfx-bench --lights --help).\n"
      "\n"
      "exit codes: 0 ok, 1 internal error, 2 usage, 3 bad input file, 4 plugin or effect error\n";
}

bool parse_bench_options(const std::vector<std::string>& list, BenchOptions* out, std::string* error) {
  BenchOptions options;
  bool sizes_given = false, frames_given = false, warmup_given = false;
  pfx::app::ArgReader args(list, error);
  while (args.next()) {
    const std::string& arg = args.arg();
    std::string text;
    auto count = [&](int* into, int lo) {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      long n = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end || n < lo || n > 100000) return args.fail(arg + " " + text + ": expected a whole number >= " + std::to_string(lo));
      *into = static_cast<int>(n);
      return true;
    };
    if (arg == "-h" || arg == "--help") options.help = true;
    else if (arg == "--quick") options.quick = true;
    else if (arg == "--no-shift") options.shift = false;
    else if (arg == "--plugins") { if (!args.value(&options.plugin_dirs)) return false; }
    else if (arg == "--out") { if (!args.value(&text)) return false; options.out_dir = text; }
    else if (arg == "--suite") { if (!args.value(&text)) return false; options.suite_file = text; }
    else if (arg == "--effects") { if (!args.value(&text)) return false; options.effects = pfx::app::split_list(text); }
    else if (arg == "--set") { if (!args.value(&options.sets)) return false; }
    else if (arg == "--input") { if (!args.value(&options.inputs)) return false; }
    else if (arg == "--layer") { if (!args.value(&options.layer)) return false; }
    else if (arg == "--truth") { if (!args.value(&options.truths)) return false; }
    else if (arg == "--halo-mask") { if (!args.value(&options.halo_masks)) return false; }
    else if (arg == "--camera") {
      if (!args.value(&text) || !pfx::app::parse_camera_options(text, &options.camera, error)) return false;
    } else if (arg == "--halo-tolerance") {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      options.halo_tolerance = std::strtod(text.c_str(), &end);
      if (text.empty() || *end || !(options.halo_tolerance >= 0))
        return args.fail("--halo-tolerance " + text + ": expected a number >= 0");
    }
    else if (arg == "--frames") { if (!count(&options.frames, 1)) return false; frames_given = true; }
    else if (arg == "--warmup") { if (!count(&options.warmup, 0)) return false; warmup_given = true; }
    else if (arg == "--timing") {
      if (!args.value(&text)) return false;
      if (text != "auto" && text != "gpu" && text != "finish") return args.fail("--timing " + text + ": expected auto, gpu or finish");
      options.timing = text;
    } else if (arg == "--sizes") {
      if (!args.value(&text) || !pfx::app::parse_frame_sizes("--sizes", text, &options.sizes, error)) return false;
      if (options.sizes.empty()) return args.fail("--sizes needs at least one size");
      sizes_given = true;
    } else {
      return args.unknown();
    }
  }
  if (!options.layer.empty() && options.inputs.empty()) return args.fail("--layer goes with --input");
  if (!options.inputs.empty() && sizes_given) return args.fail("--sizes and --input exclude each other (an input has its size)");
  if (!options.truths.empty() && options.truths.size() != options.inputs.size())
    return args.fail("give one --truth per --input (" + std::to_string(options.inputs.size()) + " inputs, " +
                std::to_string(options.truths.size()) + " truths)");
  if (!options.halo_masks.empty() && options.halo_masks.size() != options.truths.size())
    return args.fail("give one --halo-mask per --truth");
  if (options.quick) {
    if (!sizes_given && options.inputs.empty()) options.sizes = {{640, 360}};
    if (!frames_given) options.frames = 5;
    if (!warmup_given) options.warmup = 2;
  }
  *out = options;
  return true;
}

}  // namespace pfx::bench
