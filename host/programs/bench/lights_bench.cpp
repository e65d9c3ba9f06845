#include "lights_bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <glad/gl.h>
#include <nlohmann/json.hpp>

#include <pfx/host/chain.hpp>

#include "demo_scene.hpp"
#include "exit_codes.hpp"
#include "bench_timing.hpp"
#include "gbuffer.hpp"
#include "headless_context.hpp"
#include "image_texture.hpp"
#include "light_field_scene.hpp"
#include "light_reach.hpp"
#include "lights_bench_report.hpp"
#include "lights_options.hpp"
#include "plugin_directory.hpp"
#include "timing_choice.hpp"

namespace pfx::bench {
namespace {

// The scheme every measurement here uses: what suits the renderer (timing_choice.hpp).
pfx::host::Timing renderer_timing() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return pfx::app::default_timing(renderer ? renderer : "");
}

// The copy pass at a size, timed as the chain times its passes: a median of frames.
double copy_ms(int width, int height, int frames) {
  gl::CopyPass copy;
  const uint32_t a = pfx::app::create_color_texture(width, height), b = pfx::app::create_color_texture(width, height);
  time_copy(copy, a, b, width, height, renderer_timing());  // warm-up: the first use compiles
  std::vector<double> times;
  for (int i = 0; i < frames; ++i) times.push_back(time_copy(copy, a, b, width, height, renderer_timing()));
  pfx::app::delete_texture(a);
  pfx::app::delete_texture(b);
  return median(times);
}

// One chain of tiledlights over a scene's G-buffer at one size.
class Stage {
 public:
  Stage(const pfx::host::PluginRegistry& registry, const pfx::app::Scene& scene, int width, int height)
      : scene_(scene), width_(width), height_(height) {
    std::string error;
    renderer_ = pfx::app::SceneRenderer::create(scene_, &error);
    if (!renderer_) throw std::runtime_error(error);
    renderer_->render(scene_.camera, width, height);
    frame_ = pfx::app::make_scene_frame(scene_, scene_.camera, width, height);
    params_.add_effect(registry.find_effect("tiledlights")->desc);
    chain_ = std::make_unique<pfx::host::Chain>(registry, params_);
    chain_->set_timing(renderer_timing());
    if (!chain_->add("tiledlights", &error)) throw std::runtime_error(error);
    output_ = pfx::app::create_color_texture(width, height);
  }
  ~Stage() { pfx::app::delete_texture(output_); }

  void set(const std::string& assignment) {
    std::string error;
    if (!params_.set_assignment("tiledlights." + assignment, &error)) throw std::runtime_error(error);
  }

  // Medians over frames after warm-up; the effect's report of the last frame.
  struct Measured {
    double cull_ms = 0, shade_ms = 0, total_ms = 0;
    nlohmann::json report;
  };
  Measured measure(int frames, int warmup) {
    std::vector<double> cull, shade, total;
    std::string error;
    Measured m;
    for (int i = 0; i < warmup + frames; ++i) {
      frame_.frame_index = uint64_t(i);
      if (!chain_->render(frame_, renderer_->textures(), output_, &error)) throw std::runtime_error(error);
      if (i < warmup) continue;
      chain_->wait_for_timings();  // this frame's times, as the copy pass's
      double c = 0, s = 0;
      for (const auto& pass : chain_->report().passes) (pass.pass == "cull" ? c : s) += pass.ms;
      cull.push_back(c);
      shade.push_back(s);
      total.push_back(chain_->report().times.total_ms);
    }
    m.cull_ms = median(cull);
    m.shade_ms = median(shade);
    m.total_ms = median(total);
    for (const auto& [effect, members] : chain_->report().effect_reports)
      if (effect == "tiledlights") m.report = nlohmann::json::parse("{" + members + "}", nullptr, false);
    return m;
  }

  std::vector<float> output_bottom_first() const {
    return pfx::app::flip_rows(pfx::app::download_color_texture(output_, width_, height_).rgba, width_, height_, 4);
  }
  const pfx_frame& frame() const { return frame_; }
  const pfx::host::ParamStore& params() const { return params_; }
  pfx::app::SceneRenderer& renderer() { return *renderer_; }
  std::string timing() const { return chain_->report().timing; }

 private:
  const pfx::app::Scene& scene_;
  int width_, height_;
  std::unique_ptr<pfx::app::SceneRenderer> renderer_;
  pfx_frame frame_{};
  pfx::host::ParamStore params_;
  std::unique_ptr<pfx::host::Chain> chain_;
  uint32_t output_ = 0;
};

std::vector<float> read_texture(uint32_t texture, int width, int height, GLenum format) {
  std::vector<float> data(static_cast<size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
  return data;
}

void fill_cell(LightsCell* cell, const Stage::Measured& m) {
  cell->ran = true;
  cell->cull_ms = m.cull_ms;
  cell->shade_ms = m.shade_ms;
  cell->total_ms = m.total_ms;
  const auto& r = m.report;
  if (!r.is_object()) return;
  cell->lights_in_view = r.value("lights_uploaded", uint64_t(0));
  cell->lists = r.value("lists", uint64_t(0));
  cell->list_mean = r.value("list_mean", 0.0);
  cell->list_max = r.value("list_max", uint64_t(0));
  cell->list_entries = r.value("list_entries", uint64_t(0));
  cell->ssbo_bytes = r.value("ssbo_bytes", uint64_t(0));
}

void run_sweep(const LightsOptions& o, const pfx::host::PluginRegistry& registry, LightsResults* results) {
  for (const auto& [w, h] : o.sizes) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const double unit = copy_ms(w, h, std::max(o.frames, 3));
    results->copy_ms.push_back({size, unit});
    std::fprintf(stderr, "pfx-bench --lights: %s copy pass %.3f ms\n", size.c_str(), unit);
    double brute_ms_per_light = -1;  // from the last brute cell that ran at this size
    for (int count : o.counts) {
      const pfx::app::Scene scene = pfx::app::make_light_field_scene(count, o.seed);
      double brute_total = 0;
      bool brute_estimated = false;
      for (const auto& mode : o.modes) {
        LightsCell cell;
        cell.width = w;
        cell.height = h;
        cell.lights = count;
        cell.mode = mode;
        // A fresh instance per mode: an instance keeps the largest buffers it has needed, so a
        // shared one would report an earlier mode's storage as this one's.
        Stage stage(registry, scene, w, h);
        stage.set("mode=" + mode);
        // Brute force is linear in the lights that reach anything: its time per frame is predicted
        // from the last count that ran. Past the limit for one frame it is not run; otherwise it
        // times as many of the frames (warm-up first to go) as fit in the limit.
        const double predicted_ms = mode == "brute" && brute_ms_per_light > 0 ? brute_ms_per_light * count : 0;
        int frames = o.frames, warmup = o.warmup;
        if (predicted_ms > o.brute_limit_s * 1000) {
          cell.total_ms = cell.shade_ms = predicted_ms;
          brute_estimated = true;
        } else {
          if (predicted_ms * (frames + warmup) > o.brute_limit_s * 1000) {
            warmup = 0;
            frames = std::clamp(int(o.brute_limit_s * 1000 / predicted_ms), 1, o.frames);
          }
          cell.frames = frames;
          cell.warmup = warmup;
          fill_cell(&cell, stage.measure(frames, warmup));
          results->timing = stage.timing();
          if (mode == "brute" && count > 0) brute_ms_per_light = cell.total_ms / count;
        }
        if (mode == "brute") brute_total = cell.total_ms;
        cell.ratio_to_copy = unit > 0 ? cell.total_ms / unit : 0;
        std::fprintf(stderr, "pfx-bench --lights: %s %6d lights %-9s %s cull %9.3f shade %9.3f total %9.3f ms\n",
                     size.c_str(), count, mode.c_str(), cell.ran ? "" : "(estimated)", cell.cull_ms, cell.shade_ms,
                     cell.total_ms);
        results->cells.push_back(cell);
      }
      for (auto& cell : results->cells)
        if (cell.width == w && cell.height == h && cell.lights == count && brute_total > 0 && cell.total_ms > 0) {
          cell.speedup = brute_total / cell.total_ms;
          cell.speedup_estimated = brute_estimated;
        }
    }
  }
}

// The dense case: the same room with ever more lights, so each pixel is reached by more of them.
// Brute force is always measured, so every speed-up is against a brute-force frame of this run.
void run_dense(const LightsOptions& o, const pfx::host::PluginRegistry& registry, LightsResults* results) {
  const auto [w, h] = o.dense_size;
  results->dense_seed = o.dense_seed;
  const double unit = copy_ms(w, h, std::max(o.frames, 3));
  for (int count : o.dense_counts) {
    const pfx::app::Scene scene = pfx::app::make_demo_scene({count, o.dense_seed});
    double brute_total = 0;
    const size_t first = results->dense_cells.size();
    for (const auto& mode : o.modes) {
      LightsCell cell;
      cell.width = w;
      cell.height = h;
      cell.lights = count;
      cell.mode = mode;
      Stage stage(registry, scene, w, h);
      stage.set("mode=" + mode);
      int frames = o.frames, warmup = o.warmup;
      if (mode == "brute") {
        // One untimed frame costs as much as a timed one: time one, then as many as fit the limit.
        const Stage::Measured one = stage.measure(1, 0);
        frames = std::clamp(int(o.brute_limit_s * 1000 / std::max(one.total_ms, 1.0)), 1, o.frames);
        warmup = 0;
        fill_cell(&cell, frames > 1 ? stage.measure(frames, 0) : one);
        brute_total = cell.total_ms;
        const auto textures = stage.renderer().textures();
        std::vector<float> depth4 = read_texture(textures.depth, w, h, GL_RGBA), depth(size_t(w) * h);
        for (size_t i = 0; i < depth.size(); ++i) depth[i] = depth4[i * 4];
        // tiledlights' default cutoff and tile size.
        const LightReach reach =
            count_light_reach(stage.frame(), depth, read_texture(textures.normal, w, h, GL_RGBA), 0.05, 16);
        cell.reach_mean = reach.reaching_mean;
        cell.lit_mean = reach.lit_mean;
        cell.tile_reach_mean = reach.tile_reaching_mean;
      } else {
        fill_cell(&cell, stage.measure(frames, warmup));
      }
      cell.frames = frames;
      cell.warmup = warmup;
      cell.ratio_to_copy = unit > 0 ? cell.total_ms / unit : 0;
      std::fprintf(stderr, "pfx-bench --lights: dense %dx%d %6d more lights %-9s cull %9.3f shade %9.3f total %9.3f ms\n",
                   w, h, count, mode.c_str(), cell.cull_ms, cell.shade_ms, cell.total_ms);
      results->dense_cells.push_back(cell);
    }
    for (size_t i = first; i < results->dense_cells.size(); ++i) {
      LightsCell& cell = results->dense_cells[i];
      if (brute_total > 0 && cell.total_ms > 0) cell.speedup = brute_total / cell.total_ms;
    }
  }
}

void run_cutoffs(const LightsOptions& o, const pfx::host::PluginRegistry& registry, LightsResults* results) {
  const auto [w, h] = o.error_size;
  results->error_width = w;
  results->error_height = h;
  results->error_lights = o.error_lights;
  results->error_mode = o.error_mode;
  const double unit = copy_ms(w, h, 3);
  const pfx::app::Scene scene = pfx::app::make_light_field_scene(o.error_lights, o.seed);
  Stage stage(registry, scene, w, h);
  stage.set("mode=" + o.error_mode);
  const auto textures = stage.renderer().textures();
  // The G-buffer as the reference takes it: RGBA floats, rows bottom first (GL's order).
  auto read = [&](uint32_t texture) { return read_texture(texture, w, h, GL_RGBA); };
  const std::vector<float> color = read(textures.color), normal = read(textures.normal), albedo = read(textures.albedo),
                           emissive = read(textures.emissive);
  std::vector<float> depth4 = read(textures.depth), depth(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < depth.size(); ++i) depth[i] = depth4[i * 4];
  const pfx::host::EffectInfo* info = registry.find_effect("tiledlights");
  const pfx_reference_factory* references = info->plugin->references;
  std::vector<float> ideal(color.size());
  std::vector<std::pair<std::string, double>> points;
  for (double c : o.cutoffs) points.push_back({"cutoff", c});
  points.push_back({"seed", 0});
  bool ideal_done = false;
  for (const auto& [rule, cutoff] : points) {
    stage.set("range_rule=" + rule);
    if (rule == "cutoff") stage.set("cutoff=" + std::to_string(cutoff));
    const Stage::Measured m = stage.measure(o.frames, o.warmup);
    if (!ideal_done && references) {
      // The un-windowed sum does not depend on the cutoff: one evaluation serves every point.
      pfx_reference_request request{};
      request.struct_size = sizeof request;
      request.effect_id = "tiledlights";
      request.kind = PFX_REFERENCE_IDEAL;
      request.frame = &stage.frame();
      request.params = stage.params().values("tiledlights");
      request.color = color.data();
      request.depth = depth.data();
      request.normal = normal.data();
      request.albedo = albedo.data();
      request.emissive = emissive.data();
      request.output = ideal.data();
      if (references->evaluate(&request) != PFX_OK) throw std::runtime_error("the ideal reference failed");
      ideal_done = true;
    }
    CutoffPoint point;
    point.rule = rule;
    point.cutoff = cutoff;
    point.total_ms = m.total_ms;
    point.ratio_to_copy = unit > 0 ? m.total_ms / unit : 0;
    point.list_mean = m.report.is_object() ? m.report.value("list_mean", 0.0) : 0.0;
    if (ideal_done) point.error = compare_rgb(stage.output_bottom_first(), ideal, &color);
    std::fprintf(stderr, "pfx-bench --lights: error %s %g: %.3f ms, RMSE/change %.4g\n", rule.c_str(), cutoff,
                 point.total_ms, point.error.change_relative_rmse);
    results->cutoffs.push_back(point);
  }
  if (!ideal_done) results->notes.push_back("the plugin has no ideal reference: no error column");
}

}  // namespace

int lights_bench_main(const std::vector<std::string>& args) {
  LightsOptions options;
  std::string message;
  if (!parse_lights_options(args, &options, &message)) {
    std::fprintf(stderr, "pfx-bench --lights: %s\n\n%s", message.c_str(), lights_usage().c_str());
    return exit_code::kUsage;
  }
  if (options.help) {
    std::fputs(lights_usage().c_str(), stdout);
    return exit_code::kOk;
  }
  auto context = pfx::app::HeadlessContext::create(&message);
  if (!context) {
    std::fprintf(stderr, "pfx-bench --lights: %s\n", message.c_str());
    return exit_code::kInternal;
  }
  pfx::host::PluginRegistry registry(
      [](const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); },
      pfx::host::stderr_log_sink(PFX_LOG_WARNING), "pfx-bench");
  pfx::app::load_plugins(registry, options.plugin_dirs);
  if (!registry.find_effect("tiledlights")) {
    std::fprintf(stderr, "pfx-bench --lights: the tiledlights effect is not loaded\n");
    return exit_code::kEffectError;
  }
  LightsResults results;
  results.renderer = context->renderer();
  results.frames = options.frames;
  results.warmup = options.warmup;
  results.brute_limit_s = options.brute_limit_s;
  try {
    run_sweep(options, registry, &results);
    run_cutoffs(options, registry, &results);
    run_dense(options, registry, &results);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pfx-bench --lights: %s\n", e.what());
    return exit_code::kInternal;
  }
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "pfx-bench --lights: cannot create %s: %s\n", options.out_dir.c_str(), ec.message().c_str());
    return exit_code::kInternal;
  }
  if (!write_lights_reports(results, options.out_dir, &message)) {
    std::fprintf(stderr, "pfx-bench --lights: %s\n", message.c_str());
    return exit_code::kInternal;
  }
  std::fputs(lights_markdown(results).c_str(), stdout);
  return exit_code::kOk;
}

}  // namespace pfx::bench
