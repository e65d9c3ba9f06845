// The frames of a --frames run as pfx-render plans them: each frame's files (from the patterns),
// its chunk, and whether it is done. The one answer serves pfx-render, which skips the frames
// that are done, and pfx-farm, which reads it from pfx-render --print-frames (docs/farm.md).
#pragma once

#include <string>
#include <vector>

#include "render_options.hpp"

namespace pfx::app {

// The files of one frame, from the patterns of the options.
struct FrameFiles {
  long long frame = 0;
  std::string input, depth, report;
  std::vector<std::string> outputs;
};

FrameFiles frame_files(const RenderOptions& options, long long frame);

// Done: every output exists. pfx-render writes an output under a temporary name and renames it
// into place only once it is complete (atomic_file.hpp), so an output that exists is whole; the
// file is not read. pfx-farm asks the same question through --print-frames. A frame without
// outputs is done.
bool frame_done(const FrameFiles& files);

// The plan --print-frames prints: one JSON object,
//   {"frames": [{"frame": 1001, "chunk": 0, "input": "in.1001.exr", "depth": "z.1001.exr",
//                "outputs": ["out.1001.exr"], "report": "r.1001.json", "done": false}, ...],
//    "chunks": 24}
// for the frames pfx-render would render (--chunk-index: that chunk's). "chunk" and "chunks"
// come with --chunk, "depth" with --depth, "report" with --report.
std::string frame_plan_json(const RenderOptions& options);

}  // namespace pfx::app
