#include "bench_runner.hpp"

#include <algorithm>
#include <cstdio>

#include <glad/gl.h>

#include <pfx/host/chain.hpp>

#include "bench_timing.hpp"
#include "camera_options.hpp"
#include "frame_description.hpp"
#include "halo_width.hpp"
#include "image_texture.hpp"
#include "timing_choice.hpp"

namespace pfx::bench {
namespace {

std::vector<float> read_back(uint32_t texture, int w, int h) {
  return pfx::app::flip_rows(pfx::app::download_color_texture(texture, w, h).rgba, w, h, 4);
}

}  // namespace

BenchResults run_bench(const BenchOptions& options, const pfx::host::PluginRegistry& registry,
                       const std::string& renderer, const std::vector<SuiteRow>& rows,
                       const std::vector<BenchFrame>& frames) {
  BenchResults results;
  results.renderer = renderer;
  results.frames = options.frames;
  results.warmup = options.warmup;

  for (const BenchFrame& input : frames) {
    const pfx::app::Image& image = input.image;
    const int width = image.width, height = image.height;
    const uint32_t color = pfx::app::upload_color_texture(image);
    const uint32_t depth = pfx::app::upload_depth_texture(image);
    const uint32_t output = pfx::app::create_color_texture(width, height);
    // Bottom-first copies of the input for the CPU references (pfx/reference.h), and of the truth
    // and halo mask for comparing with outputs read back from GL.
    const std::vector<float> color_gl = pfx::app::flip_rows(image.rgba, width, height, 4);
    const std::vector<float> depth_gl =
        image.depth.empty() ? std::vector<float>() : pfx::app::flip_rows(image.depth, width, height, 1);
    const std::vector<float> truth_gl =
        input.truth.empty() ? std::vector<float>() : pfx::app::flip_rows(input.truth, width, height, 4);
    std::vector<uint8_t> mask_gl(input.halo_mask.size());
    for (int y = 0; y < height && !mask_gl.empty(); ++y)
      std::copy_n(input.halo_mask.begin() + static_cast<long>(y) * width, width,
                  mask_gl.begin() + static_cast<long>(height - 1 - y) * width);

    pfx_frame frame = pfx::app::describe_frame(
        width, height, PFX_INPUT_COLOR | (image.has_depth() ? static_cast<uint32_t>(PFX_INPUT_DEPTH) : 0u),
        PFX_DEPTH_LINEAR, pfx::app::make_camera(options.camera, width, height));
    pfx::host::FrameTextures textures;
    textures.color = color;
    textures.depth = depth;

    // The unit and the chains are timed the same way.
    pfx::host::Timing timing = pfx::host::Timing::GPU_QUERIES;
    pfx::app::parse_timing(options.timing, renderer, &timing);  // the name was checked with the options
    results.timing = timing == pfx::host::Timing::GPU_QUERIES ? "gpu-timestamps" : "finish+clock";
    gl::CopyPass copy;
    {
      std::vector<double> times;
      for (int i = 0; i < options.warmup + options.frames; ++i) {
        double ms = time_copy(copy, color, output, width, height, timing);
        if (i >= options.warmup) times.push_back(ms);
      }
      results.units.push_back({width, height, input.source, median(times)});
      std::fprintf(stderr, "pfx-bench: %dx%d copy pass %.3f ms\n", width, height, results.units.back().copy_ms);
    }

    for (const auto& suite_row : rows) {
      BenchRow row;
      row.effect = suite_row.effect;
      row.settings = suite_row.label();
      row.width = width;
      row.height = height;
      pfx::host::ParamStore params;
      for (const auto& effect : registry.effects()) params.add_effect(effect.desc);
      std::string message;
      bool settings_ok = true;
      std::vector<std::string> assignments = options.sets;
      for (const auto& setting : suite_row.settings) assignments.push_back(suite_row.effect + "." + setting);
      for (const auto& assignment : assignments)
        if (!params.set_assignment(assignment, &message)) {
          results.notes.push_back("row '" + suite_row.effect + " " + row.settings + "' skipped: " + message);
          settings_ok = false;
          break;
        }
      if (!settings_ok) continue;

      pfx::host::Chain chain(registry, params);
      chain.set_timing(timing);
      if (!chain.add(suite_row.effect, &message)) {
        results.notes.push_back("row '" + suite_row.effect + " " + row.settings + "' skipped: " + message);
        continue;
      }
      std::vector<double> totals;
      std::vector<std::vector<double>> per_pass;
      bool failed = false;
      // A copy pass is timed before every frame of the row, and the row's ratio is to the median of
      // those: on a shared machine the load drifts between rows, and a unit measured once at the
      // start would turn that drift into the effect's cost.
      std::vector<double> copies;
      for (int i = 0; i < options.warmup + options.frames && !failed; ++i) {
        frame.frame_index = static_cast<uint64_t>(i);
        const double copy_ms = time_copy(copy, color, output, width, height, timing);
        if (i >= options.warmup) copies.push_back(copy_ms);
        if (!chain.render(frame, textures, output, &message)) {
          results.notes.push_back("row '" + suite_row.effect + " " + row.settings + "' at " + std::to_string(width) +
                                  "x" + std::to_string(height) + " failed: " + message);
          failed = true;
          break;
        }
        if (i < options.warmup) continue;
        // The frame's own times: a benchmark may wait for them, as the copy pass's timing does.
        chain.wait_for_timings();
        const auto& report = chain.report();
        totals.push_back(report.times.total_ms);
        per_pass.resize(report.passes.size());
        for (size_t p = 0; p < report.passes.size(); ++p) per_pass[p].push_back(report.passes[p].ms);
      }
      if (failed) continue;
      const auto& report = chain.report();
      row.median_ms = median(totals);
      row.copy_ms = median(copies);
      row.ratio_to_copy = row.copy_ms > 0 ? row.median_ms / row.copy_ms : 0;
      row.peak_target_bytes = report.peak_target_bytes;
      row.pass_count = static_cast<int>(report.passes.size());
      for (size_t p = 0; p < report.passes.size(); ++p) row.passes.push_back({report.passes[p].pass, median(per_pass[p])});
      if (report.passes.empty()) row.note = "no-op with these settings";

      const pfx::host::EffectInfo* info = registry.find_effect(suite_row.effect);
      const pfx_reference_factory* references = info ? info->plugin->references : nullptr;
      if (!truth_gl.empty()) {
        const std::vector<float> out = read_back(output, width, height);
        row.error_truth = compare_rgb(out, truth_gl, &color_gl);
        if (!mask_gl.empty())
          row.halo_px = measure_halo(out, truth_gl, mask_gl, width, height, options.halo_tolerance).width;
      }
      if (references) {
        const std::vector<float> out = read_back(output, width, height);
        for (pfx_reference_kind kind : {PFX_REFERENCE_MODEL, PFX_REFERENCE_IDEAL}) {
          if (!references->has_reference(suite_row.effect.c_str(), kind)) continue;
          std::vector<float> expected(out.size());
          pfx_reference_request request{};
          request.struct_size = sizeof request;
          request.effect_id = suite_row.effect.c_str();
          request.kind = kind;
          request.frame = &frame;
          request.params = params.values(suite_row.effect);
          request.color = color_gl.data();
          request.depth = depth_gl.empty() ? nullptr : depth_gl.data();
          request.output = expected.data();
          const pfx_status status = references->evaluate(&request);
          if (status == PFX_MISSING_INPUT) {
            // These frames are images (colour, depth), not scenes: a lighting effect's reference
            // needs a G-buffer and lights. pfx-bench --lights measures it on a scene of its own.
            results.notes.push_back("reference of '" + suite_row.effect + "' needs inputs these frames lack (" +
                                    row.settings + "); effects that light a scene are measured by pfx-bench --lights");
            break;  // the other kind needs the same inputs
          }
          if (status != PFX_OK) {
            results.notes.push_back("reference of '" + suite_row.effect + "' failed for " + row.settings);
            continue;
          }
          (kind == PFX_REFERENCE_MODEL ? row.error_model : row.error_ideal) = compare_rgb(out, expected, &color_gl);
        }
      }
      if (options.shift && !report.passes.empty()) {
        ShiftFigures figures;
        if (measure_shift(chain, frame, depth, &figures, &message))
          row.shift = figures;
        else
          results.notes.push_back("shift probe of '" + suite_row.effect + " " + row.settings + "' failed: " + message);
      }
      std::fprintf(stderr, "pfx-bench: %dx%d %-12s %-30s %8.3f ms  x%.2f copy\n", width, height, row.effect.c_str(),
                   row.settings.c_str(), row.median_ms, row.ratio_to_copy);
      results.rows.push_back(std::move(row));
    }
    pfx::app::delete_texture(color);
    pfx::app::delete_texture(depth);
    pfx::app::delete_texture(output);
  }
  return results;
}

}  // namespace pfx::bench
