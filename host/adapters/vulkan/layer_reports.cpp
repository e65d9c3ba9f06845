#include "layer_reports.hpp"

#include <string>

#include "layer_calls.hpp"
#include "present_stats.hpp"
#include "timings_channel.hpp"

namespace pfx::vulkan_layer {
namespace {

// The times between presents, how many ran a pass, the chain, and the unit: a copy pass timed on
// the bridge's GL context at the frame's size (none in --bench's "application alone", which
// touches no GL).
struct BenchStats {
  inject::PresentStats presents;
  double copy_pass_ms = 0;
  std::string chain = "none";
};

// Both never freed: a thread of the application may present while the process exits.
BenchStats& bench_stats() {
  static auto* stats = new BenchStats;
  return *stats;
}

inject::TimingsChannel& timings_channel() {
  static auto* channel = new inject::TimingsChannel(layer_inject_settings().timings_file);
  return *channel;
}

bool bench_wanted() { return !layer_inject_settings().stats_file.empty(); }

void offer_pass_times(pfx_vk_bridge* bridge, uint64_t frame) {
  if (!timings_channel().enabled()) return;
  pfx_vk_frame_times times{};
  times.struct_size = sizeof times;
  if (pfx_vk_bridge_frame_times(bridge, &times) != PFX_VK_OK) return;
  host::FrameReport report;
  report.timing = times.timing;
  report.times.frame = times.frame;
  report.times.total_ms = times.total_ms;
  for (uint32_t i = 0; i < times.pass_count; ++i)
    report.times.passes.push_back({times.passes[i].effect, times.passes[i].pass, times.passes[i].ms});
  std::string error;
  if (!timings_channel().offer(frame, pfx_vk_bridge_chain(bridge), report, &error))
    log_once("timings", "the pass times for the panel could not be written: " + error);
}

}  // namespace

void report_present() {
  if (bench_wanted()) bench_stats().presents.presented();
}

void report_run(pfx_vk_bridge* bridge, const pfx_vk_image& image, uint64_t frame) {
  offer_pass_times(bridge, frame);
  if (!bench_wanted()) return;
  BenchStats& stats = bench_stats();
  if (pfx_vk_bridge_ran_passes(bridge)) stats.presents.ran_chain();
  stats.chain = pfx_vk_bridge_chain(bridge);
  // Frame 5, as in OpenGL applications: inside the warm-up the median leaves out.
  if (frame == 5) stats.copy_pass_ms = pfx_vk_bridge_copy_pass_ms(bridge, image.width, image.height);
}

void write_bench_stats() {
  if (!bench_wanted()) return;
  const auto& settings = layer_inject_settings();
  const BenchStats& stats = bench_stats();
  std::string error;
  if (!stats.presents.write(settings.stats_file, stats.copy_pass_ms, settings.bypass ? "bypass" : "chain",
                            settings.bypass ? "application alone" : stats.chain, &error))
    log_line("frame times not written: " + error);
}

}  // namespace pfx::vulkan_layer
