#include "bench_runner.hpp"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <glad/gl.h>

#include <pfx/host/chain.hpp>

#include "bench_gl_frame.hpp"
#include "bench_timing.hpp"
#include "halo_width.hpp"
#include "image_texture.hpp"
#include "timing_choice.hpp"

namespace pfx::bench {
namespace {

// The unit and the chains are timed the same way; the results name how.
pfx::host::Timing choose_timing(const BenchOptions& options, const std::string& renderer, BenchResults* results) {
  pfx::host::Timing timing = pfx::host::Timing::GPU_QUERIES;
  pfx::app::parse_timing(options.timing, renderer, &timing);  // the name was checked with the options
  results->timing = timing == pfx::host::Timing::GPU_QUERIES ? "gpu-timestamps" : "finish+clock";
  return timing;
}

// The medians of a row's measured frames, and what its chain's last report says.
void summarize_row(const pfx::host::Chain& chain, const std::vector<double>& totals, const std::vector<double>& copies,
                   const std::vector<std::vector<double>>& per_pass, BenchRow* row) {
  const auto& report = chain.report();
  row->median_ms = median(totals);
  row->copy_ms = median(copies);
  row->ratio_to_copy = row->copy_ms > 0 ? row->median_ms / row->copy_ms : 0;
  row->peak_target_bytes = report.peak_target_bytes;
  row->pass_count = static_cast<int>(report.passes.size());
  for (size_t p = 0; p < report.passes.size(); ++p) row->passes.push_back({report.passes[p].pass, median(per_pass[p])});
  if (report.passes.empty()) row->note = "no-op with these settings";
}

// The measurements on one frame: the copy pass alone (the size's unit), then one suite row at a time.
class FrameBench {
 public:
  FrameBench(const BenchOptions& options, const pfx::host::PluginRegistry& registry, pfx::host::Timing timing,
             GlBenchFrame& gl, BenchResults& results)
      : options_(options), registry_(registry), timing_(timing), gl_(gl), results_(results) {}

  void measure_unit(const std::string& source) {
    std::vector<double> times;
    for (int i = 0; i < options_.warmup + options_.frames; ++i) {
      double ms = time_copy(copy_, gl_.color, gl_.output, gl_.width, gl_.height, timing_);
      if (i >= options_.warmup) times.push_back(ms);
    }
    results_.units.push_back({gl_.width, gl_.height, source, median(times)});
    std::fprintf(stderr, "pfx-bench: %dx%d copy pass %.3f ms\n", gl_.width, gl_.height, results_.units.back().copy_ms);
  }

  void run_row(const SuiteRow& suite_row) {
    BenchRow row;
    row.effect = suite_row.effect;
    row.settings = suite_row.label();
    row.width = gl_.width;
    row.height = gl_.height;
    const std::string name = "row '" + suite_row.effect + " " + row.settings + "'";
    std::string message;
    // An 8-bit frame holds nothing above 1.0: its rows start from the display-referred defaults, as
    // in every host of such frames.
    pfx::host::ParamStore params(gl_.eight_bit() ? pfx::host::DefaultSet::DISPLAY_REFERRED
                                                 : pfx::host::DefaultSet::SCENE_REFERRED);
    if (!set_params(suite_row, &params, &message)) {
      results_.notes.push_back(name + " skipped: " + message);
      return;
    }
    pfx::host::Chain chain(registry_, params);
    chain.set_timing(timing_);
    if (!chain.add(suite_row.effect, &message)) {
      results_.notes.push_back(name + " skipped: " + message);
      return;
    }
    if (!time_row(chain, &row, &message)) {
      results_.notes.push_back(name + " at " + std::to_string(gl_.width) + "x" + std::to_string(gl_.height) +
                               " failed: " + message);
      return;
    }
    measure_truth_error(&row);
    measure_reference_errors(params, &row);
    if (options_.shift && !chain.report().passes.empty()) {
      ShiftFigures figures;
      if (measure_shift(chain, gl_.frame, gl_.depth, &figures, &message))
        row.shift = figures;
      else
        results_.notes.push_back("shift probe of '" + row.effect + " " + row.settings + "' failed: " + message);
    }
    std::fprintf(stderr, "pfx-bench: %dx%d %-12s %-30s %8.3f ms  x%.2f copy\n", gl_.width, gl_.height,
                 row.effect.c_str(), row.settings.c_str(), row.median_ms, row.ratio_to_copy);
    results_.rows.push_back(std::move(row));
  }

 private:
  // Every --set first, then the row's own settings.
  bool set_params(const SuiteRow& suite_row, pfx::host::ParamStore* params, std::string* message) const {
    for (const auto& effect : registry_.effects()) params->add_effect(effect.desc);
    std::vector<std::string> assignments = options_.sets;
    for (const auto& setting : suite_row.settings) assignments.push_back(suite_row.effect + "." + setting);
    for (const auto& assignment : assignments)
      if (!params->set_assignment(assignment, message)) return false;
    return true;
  }

  // A copy pass is timed before every frame of the row, and the row's ratio is to the median of
  // those: on a shared machine the load drifts between rows, and a unit measured once at the
  // start would turn that drift into the effect's cost.
  bool time_row(pfx::host::Chain& chain, BenchRow* row, std::string* message) {
    std::vector<double> totals, copies;
    std::vector<std::vector<double>> per_pass;
    for (int i = 0; i < options_.warmup + options_.frames; ++i) {
      gl_.frame.frame_index = static_cast<uint64_t>(i);
      const double copy_ms = time_copy(copy_, gl_.color, gl_.output, gl_.width, gl_.height, timing_);
      if (i >= options_.warmup) copies.push_back(copy_ms);
      if (!chain.render(gl_.frame, gl_.textures, gl_.chain_output(), message)) return false;
      if (i < options_.warmup) continue;
      // The frame's own times: a benchmark may wait for them, as the copy pass's timing does.
      chain.wait_for_timings();
      const auto& report = chain.report();
      totals.push_back(report.times.total_ms);
      per_pass.resize(report.passes.size());
      for (size_t p = 0; p < report.passes.size(); ++p) per_pass[p].push_back(report.passes[p].ms);
    }
    summarize_row(chain, totals, copies, per_pass, row);
    return true;
  }

  // Against --truth, with the halo's width where --halo-mask gave the object.
  void measure_truth_error(BenchRow* row) const {
    if (gl_.truth_gl.empty()) return;
    const std::vector<float> out = gl_.read_result();
    row->error_truth = compare_rgb(out, gl_.truth_gl, &gl_.color_gl);
    if (!gl_.mask_gl.empty())
      row->halo_px = measure_halo(out, gl_.truth_gl, gl_.mask_gl, gl_.width, gl_.height, options_.halo_tolerance).width;
  }

  // Against the CPU references the effect's plugin ships, model and ideal.
  void measure_reference_errors(const pfx::host::ParamStore& params, BenchRow* row) {
    const pfx::host::EffectInfo* info = registry_.find_effect(row->effect);
    const pfx_reference_factory* references = info ? info->plugin->references : nullptr;
    if (!references) return;
    const std::vector<float> out = gl_.read_result();
    for (pfx_reference_kind kind : {PFX_REFERENCE_MODEL, PFX_REFERENCE_IDEAL}) {
      if (!references->has_reference(row->effect.c_str(), kind)) continue;
      std::vector<float> expected(out.size());
      const pfx_status status = evaluate_reference(*references, row->effect, kind, params.values(row->effect),
                                                   &expected);
      if (status == PFX_MISSING_INPUT) {
        // These frames are images (colour, depth), not scenes: a lighting effect's reference
        // needs a G-buffer and lights. pfx-bench --lights measures it on a scene of its own.
        results_.notes.push_back("reference of '" + row->effect + "' needs inputs these frames lack (" + row->settings +
                                 "); effects that light a scene are measured by pfx-bench --lights");
        break;  // the other kind needs the same inputs
      }
      if (status != PFX_OK) {
        results_.notes.push_back("reference of '" + row->effect + "' failed for " + row->settings);
        continue;
      }
      (kind == PFX_REFERENCE_MODEL ? row->error_model : row->error_ideal) = compare_rgb(out, expected, &gl_.color_gl);
    }
  }

  // The reference's picture of this frame, into *expected (sized as the output).
  pfx_status evaluate_reference(const pfx_reference_factory& references, const std::string& effect,
                                pfx_reference_kind kind, const pfx_value* values, std::vector<float>* expected) const {
    pfx_reference_request request{};
    request.struct_size = sizeof request;
    request.effect_id = effect.c_str();
    request.kind = kind;
    request.frame = &gl_.frame;
    request.params = values;
    request.color = gl_.color_gl.data();
    request.depth = gl_.depth_gl.empty() ? nullptr : gl_.depth_gl.data();
    request.output = expected->data();
    return references.evaluate(&request);
  }

  const BenchOptions& options_;
  const pfx::host::PluginRegistry& registry_;
  const pfx::host::Timing timing_;
  GlBenchFrame& gl_;
  BenchResults& results_;
  gl::CopyPass copy_;
};

}  // namespace

BenchResults run_bench(const BenchOptions& options, const pfx::host::PluginRegistry& registry,
                       const std::string& renderer, const std::vector<SuiteRow>& rows,
                       const std::vector<BenchFrame>& frames) {
  BenchResults results;
  results.renderer = renderer;
  results.frames = options.frames;
  results.warmup = options.warmup;
  for (const BenchFrame& input : frames) {
    GlBenchFrame gl;
    std::string error;
    if (!upload_gl_bench_frame(input, options.camera, &gl, &error)) {
      results.notes.push_back(input.source + " not measured: " + error);
      release_gl_bench_frame(gl);
      continue;
    }
    const pfx::host::Timing timing = choose_timing(options, renderer, &results);
    {
      FrameBench bench(options, registry, timing, gl, results);
      bench.measure_unit(input.source);
      for (const auto& suite_row : rows) bench.run_row(suite_row);
    }
    release_gl_bench_frame(gl);
  }
  return results;
}

}  // namespace pfx::bench
