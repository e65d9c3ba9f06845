#include "frame_plan.hpp"

#include <filesystem>

#include <nlohmann/json.hpp>

namespace pfx::app {

FrameFiles frame_files(const RenderOptions& options, long long frame) {
  auto expand = [&](const std::string& path) {
    FramePattern pattern;
    std::string ignored;
    return parse_frame_pattern("", path, &pattern, &ignored) ? pattern.path(frame) : path;
  };
  FrameFiles files;
  files.frame = frame;
  files.input = expand(options.input);
  if (!options.depth.empty()) files.depth = expand(options.depth);
  if (!options.sequence.report.empty()) files.report = expand(options.sequence.report);
  for (const auto& path : options.outputs) files.outputs.push_back(expand(path));
  return files;
}

bool frame_done(const FrameFiles& files) {
  std::error_code error;
  for (const auto& path : files.outputs)
    if (!std::filesystem::is_regular_file(path, error)) return false;
  return true;
}

std::string frame_plan_json(const RenderOptions& options) {
  const SequenceOptions& sequence = options.sequence;
  const FrameRange range = frames_to_render(sequence);
  // A chunk's frames are numbered among the whole range's.
  const long long first_index = (range.first - sequence.frames.first) / sequence.frames.step;
  nlohmann::ordered_json plan;
  plan["frames"] = nlohmann::ordered_json::array();
  for (long long index = 0; index < range.count(); ++index) {
    const FrameFiles files = frame_files(options, range.at(index));
    nlohmann::ordered_json frame = {{"frame", files.frame}};
    if (sequence.chunk) frame["chunk"] = (first_index + index) / sequence.chunk;
    frame["input"] = files.input;
    if (!files.depth.empty()) frame["depth"] = files.depth;
    frame["outputs"] = files.outputs;
    if (!files.report.empty()) frame["report"] = files.report;
    frame["done"] = frame_done(files);
    plan["frames"].push_back(frame);
  }
  if (sequence.chunk) plan["chunks"] = chunk_count(sequence.frames, sequence.chunk);
  return plan.dump(2) + "\n";
}

}  // namespace pfx::app
