#include "sequence_options.hpp"

namespace pfx::app {

bool parse_sequence_option(ArgReader& args, SequenceOptions* out, bool* taken) {
  const std::string& arg = args.arg();
  *taken = true;
  std::string text, error;
  if (arg == "--frames") {
    if (!args.value(&text)) return false;
    if (!parse_frame_range(text, &out->frames, &error)) return args.fail(error);
    out->given = true;
  } else if (arg == "--overwrite") {
    out->overwrite = true;
  } else if (arg == "--report") {
    if (!args.value(&out->report)) return false;
  } else {
    *taken = false;
  }
  return true;
}

bool check_sequence_options(const SequenceOptions& sequence, const std::string& input, const std::string& depth,
                            const std::vector<std::string>& outputs, bool other_source, std::string* error) {
  FramePattern pattern;
  if (!sequence.given) {
    if (sequence.overwrite) return *error = "--overwrite goes with --frames", false;
    if (!sequence.report.empty()) return *error = "--report goes with --frames", false;
    for (const auto& path : outputs)
      if (has_printf_frame_token(path))
        return *error = "--out " + path + " names a frame sequence: give --frames FIRST-LAST", false;
    if (has_printf_frame_token(input))
      return *error = "--input " + input + " names a frame sequence: give --frames FIRST-LAST", false;
    return true;
  }
  if (other_source || input.empty()) return *error = "--frames goes with --input (a sequence of EXR files)", false;
  if (!parse_frame_pattern("--input", input, &pattern, error)) return false;
  if (has_frame_token(depth) && !parse_frame_pattern("--depth", depth, &pattern, error)) return false;
  for (const auto& path : outputs)
    if (!parse_frame_pattern("--out", path, &pattern, error)) return false;
  if (!sequence.report.empty() && !parse_frame_pattern("--report", sequence.report, &pattern, error)) return false;
  return true;
}

}  // namespace pfx::app
