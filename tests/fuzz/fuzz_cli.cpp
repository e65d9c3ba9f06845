// libFuzzer target for our command-line parsers: pfx-render's, pfx-bench's and pfx-validate's.
// The input is an argument list, arguments separated by NUL bytes. Each parser must accept it or
// refuse it with a message, never crash or throw, and what it accepts must be in range.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "render_options.hpp"
#include "validate_options.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args(1);
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0) args.emplace_back();
    else args.back().push_back(static_cast<char>(data[i]));
  }
  if (args.size() > 64) return 0;  // longer lists find nothing new, only slow the search

  std::string error;
  pfx::app::RenderOptions render;
  if (pfx::app::parse_render_options(args, &render, &error)) {
    if (render.width < 1 || render.height < 1 || render.width > 16384 || render.height > 16384) __builtin_trap();
    if (!(render.camera.near_plane > 0) || !(render.camera.far_plane > render.camera.near_plane)) __builtin_trap();
    const pfx::app::FrameRange& frames = render.sequence.frames;
    if (render.sequence.given && (frames.first < 0 || frames.last < frames.first ||
                                  frames.last > pfx::app::kMaxFrameNumber || frames.step < 1 || frames.count() < 1))
      __builtin_trap();
    // --help and --list end the checks: they print the usage or the effects, whatever else the
    // line holds (regressions/cli/help-with-frames, list-with-frames).
    pfx::app::FramePattern pattern;
    if (render.sequence.given && !render.help && !render.list &&
        !pfx::app::parse_frame_pattern("--input", render.input, &pattern, &error))
      __builtin_trap();
  } else if (error.empty()) {
    __builtin_trap();
  }

  error.clear();
  pfx::bench::BenchOptions bench;
  if (pfx::bench::parse_bench_options(args, &bench, &error)) {
    for (const auto& [w, h] : bench.sizes)
      if (w < 1 || h < 1 || w > 16384 || h > 16384) __builtin_trap();
  } else if (error.empty()) {
    __builtin_trap();
  }

  error.clear();
  pfx::validate::ValidateOptions validate;
  if (pfx::validate::parse_validate_options(args, &validate, &error)) {
    if (validate.runs < 0 || validate.runs > 10000 || !(validate.timeout_s > 0)) __builtin_trap();
  } else if (error.empty()) {
    __builtin_trap();
  }
  return 0;
}
