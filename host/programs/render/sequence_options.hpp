// pfx-render's options for image sequences (--frames, --overwrite, --report, the chunks and the
// frame plan), parsed and checked apart from the single-frame options so the two grow without
// stepping on each other.
#pragma once

#include <string>
#include <vector>

#include "arg_reader.hpp"
#include "frame_pattern.hpp"

namespace pfx::app {

struct SequenceOptions {
  bool given = false;      // --frames was given: --input, --depth, --out and --report are patterns
  FrameRange frames;       // --frames A-B[xSTEP]
  bool overwrite = false;  // --overwrite: render frames whose outputs are already complete
  std::string report;      // --report PATTERN: each frame's JSON report to its own file
  long long chunk = 0;     // --chunk N: the range in chunks of N frames (0: not given)
  long long chunk_index = -1;  // --chunk-index I: only chunk I of them, from 0 (-1: every chunk)
  bool print_frames = false;   // --print-frames: print the frame plan as JSON, render nothing
};

// Takes args.arg() when it is one of the sequence options (with its value): *taken says whether
// it was; false on a bad value, with the reader's error set.
bool parse_sequence_option(ArgReader& args, SequenceOptions* out, bool* taken);

// The frames to render: --frames, or with --chunk-index only that chunk of them.
FrameRange frames_to_render(const SequenceOptions& sequence);

// Once every option is read: with --frames, --input, every --out and --report must be patterns
// (--depth may be one file for every frame), and --chunk-index must name one of the chunks;
// without it, %d/%0Nd in --input or --out is refused as a forgotten --frames, and the other
// sequence options are refused. False with *error.
bool check_sequence_options(const SequenceOptions& sequence, const std::string& input, const std::string& depth,
                            const std::vector<std::string>& outputs, bool other_source, std::string* error);

}  // namespace pfx::app
