// A chain's report of one frame as JSON, the same members in every program that prints one
// (pfx-render's --json and each frame of a sequence, the Python module's Chain.report).
#pragma once

#include <nlohmann/json.hpp>

#include <pfx/host/chain.hpp>

namespace pfx::app {

// "effects", "effects_skipped", "passes" ({effect, pass, ms}), "total_ms", "timing",
// "peak_target_bytes", "unpooled_target_bytes", added to `json` in that order.
void add_frame_report(const host::FrameReport& report, nlohmann::ordered_json* json);
// Each effect's own figures by effect id; an effect's report that is not valid JSON is kept as text.
nlohmann::ordered_json effect_reports_json(const host::FrameReport& report);

}  // namespace pfx::app
