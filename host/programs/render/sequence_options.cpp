#include "sequence_options.hpp"

#include <cctype>
#include <cstdlib>

namespace pfx::app {
namespace {

// A whole number from `least` to kMaxFrameNumber, the value of `option`.
bool parse_count(ArgReader& args, const std::string& option, long long least, long long* out) {
  std::string text;
  if (!args.value(&text)) return false;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])) || *end || value < least ||
      value > kMaxFrameNumber)
    return args.fail(option + " " + text + ": expected a whole number from " + std::to_string(least) + " to " +
                     std::to_string(kMaxFrameNumber));
  *out = value;
  return true;
}

}  // namespace

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
  } else if (arg == "--chunk") {
    if (!parse_count(args, arg, 1, &out->chunk)) return false;
  } else if (arg == "--chunk-index") {
    if (!parse_count(args, arg, 0, &out->chunk_index)) return false;
  } else if (arg == "--print-frames") {
    out->print_frames = true;
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
    if (sequence.chunk) return *error = "--chunk goes with --frames", false;
    if (sequence.chunk_index >= 0) return *error = "--chunk-index goes with --frames and --chunk", false;
    if (sequence.print_frames) return *error = "--print-frames goes with --frames", false;
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
  if (sequence.chunk_index >= 0) {
    if (!sequence.chunk) return *error = "--chunk-index goes with --chunk N (the chunks' size)", false;
    const long long chunks = chunk_count(sequence.frames, sequence.chunk);
    if (sequence.chunk_index >= chunks)
      return *error = "--chunk-index " + std::to_string(sequence.chunk_index) + ": the " +
                      std::to_string(sequence.frames.count()) + " frames in chunks of " +
                      std::to_string(sequence.chunk) + " make chunks 0 to " + std::to_string(chunks - 1),
             false;
  }
  return true;
}

FrameRange frames_to_render(const SequenceOptions& sequence) {
  if (sequence.chunk_index < 0) return sequence.frames;
  return chunk_of(sequence.frames, sequence.chunk, sequence.chunk_index);
}

}  // namespace pfx::app
