#include "frame_report_json.hpp"

namespace pfx::app {

void add_frame_report(const host::FrameReport& report, nlohmann::ordered_json* json) {
  nlohmann::ordered_json& root = *json;
  root["effects"] = report.effects_run;
  root["effects_skipped"] = report.effects_skipped;
  root["passes"] = nlohmann::ordered_json::array();
  for (const auto& pass : report.passes)
    root["passes"].push_back({{"effect", pass.effect}, {"pass", pass.pass}, {"ms", pass.ms}});
  root["total_ms"] = report.times.total_ms;
  root["timing"] = report.timing;
  root["peak_target_bytes"] = report.peak_target_bytes;
  root["unpooled_target_bytes"] = report.unpooled_target_bytes;
}

nlohmann::ordered_json effect_reports_json(const host::FrameReport& report) {
  nlohmann::ordered_json reports = nlohmann::ordered_json::object();
  for (const auto& [effect, members] : report.effect_reports) {
    // An effect's figures are JSON members without braces.
    auto parsed = nlohmann::ordered_json::parse("{" + members + "}", nullptr, false);
    reports[effect] = parsed.is_discarded() ? nlohmann::ordered_json(members) : parsed;
  }
  return reports;
}

}  // namespace pfx::app
