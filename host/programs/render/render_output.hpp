// The chain over one frame, and what comes out of it: the result read back, the output files,
// and the frame's report (JSON for --json and each frame of a sequence, a summary on stderr
// otherwise).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <pfx/host/chain.hpp>

#include "display_input.hpp"
#include "image.hpp"
#include "render_input.hpp"
#include "tonemap.hpp"

namespace pfx::app {

struct RenderResult {
  Image image;            // linear RGBA, as the chain left it (an 8-bit result decoded)
  DisplayImage encoded;   // an 8-bit input's result encoded back as the input was decoded
  bool has_encoded = false;
};

// Runs the chain over the input and reads the result back (for an 8-bit input: from display's
// output texture, also encoded back with `transfer`). False with *error when the chain failed.
bool render_frame(host::Chain& chain, const RenderInput& input, DisplayInput* display, Transfer transfer,
                  RenderResult* result, std::string* error);

// Whether any of the paths is not a PNG: an 8-bit input's result is then wanted in linear light.
bool wants_linear_result(const std::vector<std::string>& outputs);

// Writes every path: .exr as half (or float with float_exr), .png the encoded result when there
// is one, else the result tone-mapped with `tone`. Stops at the first failure, with *error.
bool write_outputs(const std::vector<std::string>& paths, bool float_exr, const ToneMapSettings& tone,
                   const RenderResult& result, std::string* error);

// Which channels of the input file (and depth file) became the frame.
nlohmann::ordered_json input_json(const std::string& input, const std::string& depth, const InputReport& read);

// The frame's report: renderer, input read (when `input` is not null), lights, effects, passes and
// times, target memory, the output's statistics, the files written, each effect's own report.
nlohmann::ordered_json report_json(const std::string& renderer, const pfx_frame& frame, const host::FrameReport& report,
                                   const Image& result, const std::vector<std::string>& outputs,
                                   const nlohmann::ordered_json& input);

// The same in words on stderr: the input read, the renderer, each pass's time, the total.
void print_report(const std::string& renderer, const host::FrameReport& report, const std::string& input,
                  const std::string& depth, const InputReport& read);

}  // namespace pfx::app
