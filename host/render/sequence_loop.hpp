// pfx-render over a frame range: for each frame, the file names from the patterns; a frame whose
// outputs are all complete is skipped (unless --overwrite); the others are rendered by the
// caller's function, which keeps its plugins and GL objects between calls. A frame that fails
// (missing or damaged input, an effect error, a file that cannot be written) is reported and the
// next one is rendered. Progress goes to stderr (one rewritten line on a terminal, a line per
// frame elsewhere); --json prints one JSON line per frame, then a summary line.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render_options.hpp"

namespace pfx::app {

// Exit code when at least one frame failed and the others were done.
constexpr int kSomeFramesFailed = 5;

// The files of one frame, from the patterns of the options.
struct FrameFiles {
  long long frame = 0;
  std::string input, depth, report;
  std::vector<std::string> outputs;
};

// Renders one frame: reads files.input (and files.depth), writes every files.outputs, fills
// *report with the frame's JSON report (renderer, passes, times, ...). False with *error
// ("PATH: reason") when the frame failed.
using RenderFrameFn =
    std::function<bool(const FrameFiles& files, nlohmann::ordered_json* report, std::string* error)>;

FrameFiles frame_files(const RenderOptions& options, long long frame);

// True when `path` exists and reads back whole as the image its extension says (.exr, .png),
// within max_pixels: what a finished atomic write leaves. A truncated or foreign file is not.
bool output_is_complete(const std::string& path, long long max_pixels);

// Runs every frame of options.sequence.frames; returns the exit code: 0, kSomeFramesFailed, or
// 128 + the signal when SIGINT or SIGTERM stopped it after a frame.
int run_sequence(const RenderOptions& options, const RenderFrameFn& render);

}  // namespace pfx::app
