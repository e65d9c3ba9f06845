#include "render_output.hpp"

#include <algorithm>
#include <cstdio>

#include "cli_text.hpp"
#include "exr_io.hpp"
#include "frame_report_json.hpp"
#include "image_stats.hpp"
#include "image_texture.hpp"
#include "png_io.hpp"

namespace pfx::app {

bool render_frame(host::Chain& chain, const RenderInput& input, DisplayInput* display, Transfer transfer,
                  RenderResult* result, std::string* error) {
  const pfx_frame& frame = input.frame();
  const int width = static_cast<int>(frame.width), height = static_cast<int>(frame.height);
  const uint32_t output = display ? display->output() : create_color_texture(width, height);
  const bool rendered = chain.render(frame, input.textures(), output, error);
  if (rendered) {
    // The pixels are read back next anyway, so waiting for the frame's times costs nothing.
    chain.wait_for_timings();
    if (display) result->encoded = display->encode_output(transfer);
    result->has_encoded = display != nullptr;
    // An 8-bit result is read as the PNG holds it.
    result->image = display && !display->linear_result() ? decode_display_image(result->encoded, transfer)
                                                         : download_color_texture(output, width, height);
  }
  if (!display) delete_texture(output);
  return rendered;
}

bool wants_linear_result(const std::vector<std::string>& outputs) {
  return std::any_of(outputs.begin(), outputs.end(), [](const std::string& path) { return !ends_with(path, ".png"); });
}

bool write_outputs(const std::vector<std::string>& paths, bool float_exr, const ToneMapSettings& tone,
                   const RenderResult& result, std::string* error) {
  for (const auto& path : paths) {
    const bool ok =
        ends_with(path, ".png")
            ? write_png(path, result.has_encoded ? result.encoded : tonemap_to_srgb8(result.image, tone), error)
            : write_exr(path, result.image, float_exr ? ExrPixelType::Float : ExrPixelType::Half, error);
    if (!ok) return false;
  }
  return true;
}

nlohmann::ordered_json input_json(const std::string& input, const std::string& depth, const InputReport& read) {
  nlohmann::ordered_json json = {{"file", input}, {"read", read.color}};
  if (!depth.empty()) json["depth"] = {{"file", depth}, {"read", read.depth}};
  return json;
}

nlohmann::ordered_json report_json(const std::string& renderer, const pfx_frame& frame, const host::FrameReport& report,
                                   const Image& result, const std::vector<std::string>& outputs,
                                   const nlohmann::ordered_json& input) {
  const ImageStats stats = compute_image_stats(result);
  nlohmann::ordered_json root;
  root["renderer"] = renderer;
  if (!input.is_null()) root["input"] = input;
  root["lights"] = frame.light_count;
  add_frame_report(report, &root);
  root["output"] = {{"width", stats.width}, {"height", stats.height}, {"min", stats.min}, {"max", stats.max},
                    {"mean", stats.mean}, {"nonfinite", stats.nonfinite}};
  root["files"] = outputs;
  if (!report.effect_reports.empty()) root["effect_reports"] = effect_reports_json(report);
  return root;
}

void print_report(const std::string& renderer, const host::FrameReport& report, const std::string& input,
                  const std::string& depth, const InputReport& read) {
  if (!input.empty()) {
    std::fprintf(stderr, "input: %s: %s\n", input.c_str(), read.color.c_str());
    if (!depth.empty()) std::fprintf(stderr, "depth: %s: %s\n", depth.c_str(), read.depth.c_str());
  }
  std::fprintf(stderr, "renderer: %s (timing: %s)\n", renderer.c_str(), report.timing.c_str());
  for (const auto& pass : report.passes)
    std::fprintf(stderr, "  %-12s %-16s %8.3f ms\n", pass.effect.c_str(), pass.pass.c_str(), pass.ms);
  std::fprintf(stderr, "  total %.3f ms over %zu passes; peak target memory %llu bytes\n", report.times.total_ms,
               report.passes.size(), static_cast<unsigned long long>(report.peak_target_bytes));
  if (report.passes.empty()) std::fprintf(stderr, "  no effect ran: the output is the input\n");
}

}  // namespace pfx::app
