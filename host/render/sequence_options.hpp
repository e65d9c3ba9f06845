// pfx-render's options for image sequences (--frames, --overwrite, --report), parsed and checked
// apart from the single-frame options so the two grow without stepping on each other.
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
};

// Takes args.arg() when it is one of the sequence options (with its value): *taken says whether
// it was; false on a bad value, with the reader's error set.
bool parse_sequence_option(ArgReader& args, SequenceOptions* out, bool* taken);

// Once every option is read: with --frames, --input, every --out and --report must be patterns
// (--depth may be one file for every frame); without it, %d/%0Nd in --input or --out is refused
// as a forgotten --frames, and --overwrite and --report are refused. False with *error.
bool check_sequence_options(const SequenceOptions& sequence, const std::string& input, const std::string& depth,
                            const std::vector<std::string>& outputs, bool other_source, std::string* error);

}  // namespace pfx::app
