#include "lights_options.hpp"

#include <cmath>
#include <cstdlib>

#include "arg_reader.hpp"
#include "cli_text.hpp"

namespace pfx::bench {

std::string lights_usage() {
  return "usage: pfx-bench --lights [--sizes WxH,...] [--counts N,...] [--modes m,...] [--frames N]\n"
         "                          [--warmup N] [--brute-limit S] [--error-size WxH] [--error-lights N]\n"
         "                          [--error-mode M] [--cutoffs c,...] [--seed S] [--dense-size WxH]\n"
         "                          [--dense-counts N,...] [--dense-seed S] [--out DIR]\n"
         "                          [--plugins DIR]... [--quick]\n"
         "\n"
         "Measures the tiledlights effect against its light count on the light-field scene: the demo's\n"
         "objects on a floor that grows with the count so the lights' density stays one per 4 m^2, seen\n"
         "from 20 m (from 1,000 lights on, the floor fills the view, which takes in about 560 lights:\n"
         "more lights are more lights outside it). For every size, count and mode: median cull and shade\n"
         "time, total, ratio to a plain copy pass, speed-up over brute force, lights in view, list\n"
         "length (mean, max), indices in all lists, shader storage bytes. Brute force runs only where one\n"
         "frame is predicted (from the smaller count, linearly) to finish within --brute-limit seconds,\n"
         "timing as many frames as fit (at least one, warm-up dropped first); elsewhere its time is that\n"
         "prediction, marked estimated. Then, at --error-size with --error-lights lights and\n"
         "--error-mode, time and error against the un-windowed sum (the plugin's ideal reference) for\n"
         "every cutoff and for the range rule 'seed' (3 sqrt(max colour)). Last, the dense case: the\n"
         "demo scene with N more lights in the same room (pfx-render --demo --lights N --seed S), every\n"
         "mode, brute force always measured (at least one frame), and each culled mode's speed-up over\n"
         "it; counted on the CPU, per pixel with geometry, the lights reaching its point, those whose\n"
         "term is not zero (the least any exact method sums) and those a perfectly culled 16-pixel\n"
         "tile's list holds.\n"
         "\n"
         "  --sizes      default 1280x720,1920x1080\n"
         "  --counts     default 100,1000,10000,100000\n"
         "  --modes      default brute,cpu8x4,tiled,clustered\n"
         "  --frames     timed frames per cell (default 3); --warmup untimed first (default 1)\n"
         "  --brute-limit  seconds (default 60)\n"
         "  --error-size default 640x360; --error-lights default 1000; --error-mode default tiled\n"
         "  --cutoffs    default 0.5,0.2,0.1,0.05,0.02,0.01,0.005,0.002\n"
         "  --dense-size default 320x180; --dense-counts default 10000,100000 (0: no dense case);\n"
         "  --dense-seed default 7\n"
         "  --out DIR    writes lights.json, lights.md, lights_time.png, lights_error.png (default out/bench)\n"
         "  --quick      a smoke run: 64x36, 100 and 1000 lights, 1 frame, no warm-up, two cutoffs,\n"
         "               the dense case at 64x36 with 1000 more lights\n"
         "\n"
         "exit codes: 0 ok, 1 internal error (no GL 4.5, an output not written), 2 usage,\n"
         "            4 the tiledlights plugin is not loaded\n";
}

namespace {

bool parse_number(const std::string& text, double* out) {
  char* end = nullptr;
  *out = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(*out);
}

bool is_mode(const std::string& name) {
  return name == "brute" || name == "cpu8x4" || name == "tiled" || name == "clustered";
}

}  // namespace

bool parse_lights_options(const std::vector<std::string>& list, LightsOptions* out, std::string* error) {
  LightsOptions o;
  pfx::app::ArgReader args(list, error);
  while (args.next()) {
    const std::string& arg = args.arg();
    std::string text;
    auto whole = [&](double v, double lo, double hi) { return v == std::floor(v) && v >= lo && v <= hi; };
    double number = 0;
    if (arg == "-h" || arg == "--help") o.help = true;
    else if (arg == "--quick") {
      o.sizes = {{64, 36}};
      o.counts = {100, 1000};
      o.frames = 1;
      o.warmup = 0;
      o.error_size = {64, 36};
      o.error_lights = 400;
      o.cutoffs = {0.1, 0.05};
      o.dense_size = {64, 36};
      o.dense_counts = {1000};
    } else if (arg == "--sizes") {
      if (!args.value(&text) || !pfx::app::parse_frame_sizes("--sizes", text, &o.sizes, error)) return false;
    } else if (arg == "--dense-size") {
      if (!args.value(&text) ||
          !pfx::app::parse_frame_size("--dense-size", text, &o.dense_size.first, &o.dense_size.second, error))
        return false;
    } else if (arg == "--counts" || arg == "--cutoffs" || arg == "--dense-counts") {
      if (!args.value(&text)) return false;
      std::vector<double> numbers;
      for (const auto& item : pfx::app::split_list(text)) {
        const bool count = arg != "--cutoffs";
        if (!parse_number(item, &number) || (count ? !whole(number, 0, 1e7) : !(number > 0)))
          return args.fail(arg + " " + text + ": '" + item + "' is not " +
                           (count ? "a light count from 0 to 10000000" : "a positive cutoff"));
        numbers.push_back(number);
      }
      if (arg == "--counts") {
        o.counts.clear();
        for (double n : numbers) o.counts.push_back(static_cast<int>(n));
      } else if (arg == "--dense-counts") {
        o.dense_counts.clear();
        for (double n : numbers)
          if (n > 0) o.dense_counts.push_back(static_cast<int>(n));
      } else {
        o.cutoffs = numbers;
      }
    } else if (arg == "--modes") {
      if (!args.value(&text)) return false;
      o.modes = pfx::app::split_list(text);
      for (const auto& m : o.modes)
        if (!is_mode(m))
          return args.fail("--modes: unknown mode '" + m + "' (brute, cpu8x4, tiled, clustered)");
    } else if (arg == "--error-mode") {
      if (!args.value(&text)) return false;
      o.error_mode = text;
      if (!is_mode(text)) return args.fail("--error-mode: unknown mode '" + text + "' (brute, cpu8x4, tiled, clustered)");
    } else if (arg == "--frames" || arg == "--warmup" || arg == "--error-lights" || arg == "--brute-limit" ||
               arg == "--seed" || arg == "--dense-seed") {
      if (!args.value(&text)) return false;
      const bool ok = parse_number(text, &number) &&
                      (arg == "--brute-limit" ? number >= 0 : whole(number, arg == "--frames" ? 1 : 0, 1e7));
      if (!ok) return args.fail(arg + " " + text + ": not a valid number");
      if (arg == "--frames") o.frames = int(number);
      if (arg == "--warmup") o.warmup = int(number);
      if (arg == "--error-lights") o.error_lights = int(number);
      if (arg == "--brute-limit") o.brute_limit_s = number;
      if (arg == "--seed") o.seed = uint64_t(number);
      if (arg == "--dense-seed") o.dense_seed = uint64_t(number);
    } else if (arg == "--error-size") {
      if (!args.value(&text) || !pfx::app::parse_frame_size("--error-size", text, &o.error_size.first, &o.error_size.second, error))
        return false;
    } else if (arg == "--out") {
      if (!args.value(&o.out_dir)) return false;
    } else if (arg == "--plugins") {
      if (!args.value(&o.plugin_dirs)) return false;
    } else {
      return args.fail("unknown option '" + arg + "' (see pfx-bench --lights --help)");
    }
  }
  *out = o;
  return true;
}

}  // namespace pfx::bench
