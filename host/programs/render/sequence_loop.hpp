// pfx-render over a frame range: for each frame, the file names from the patterns; a frame that is
// done (frame_plan.hpp) is skipped (unless --overwrite); the others are rendered by the
// caller's function, which keeps its plugins and GL objects between calls. A frame that fails
// (missing or damaged input, an effect error, a file that cannot be written) is reported and the
// next one is rendered. Progress goes to stderr (one rewritten line on a terminal, a line per
// frame elsewhere); --json prints one JSON line per frame, then a summary line.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frame_plan.hpp"
#include "render_options.hpp"

namespace pfx::app {

// Renders one frame: reads files.input (and files.depth), writes every files.outputs, fills
// *report with the frame's JSON report (renderer, passes, times, ...). False with *error
// ("PATH: reason") when the frame failed.
using RenderFrameFn =
    std::function<bool(const FrameFiles& files, nlohmann::ordered_json* report, std::string* error)>;

// Runs every frame of the range (--chunk-index: of that chunk); returns the exit code
// (exit_codes.hpp): kOk, kSomeFramesFailed, or kSignalBase + the signal when SIGINT or SIGTERM
// stopped it after a frame.
int run_sequence(const RenderOptions& options, const RenderFrameFn& render);

}  // namespace pfx::app
