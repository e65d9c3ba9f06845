// What the tiledlights GL tests share: a scene's G-buffer rendered by the host (host/lib/scene) and read
// back, a chain holding the tiledlights plugin (loaded from its build path), the frame, the output
// and the plugin's CPU references of the same inputs. Images are rows bottom first, RGBA.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "gbuffer.hpp"
#include "gl_test_support.hpp"
#include "scene.hpp"

namespace lights_test {

// The G-buffer of a scene as textures (owned by the renderer) and as floats.
struct Captured {
  int width = 0, height = 0;
  pfx_frame frame{};
  pfx::host::FrameTextures textures;
  std::vector<float> color, depth, normal, albedo, emissive;  // depth: one float per pixel
  std::vector<pfx_light> lights;  // the frame points here: the scene may be gone
  std::unique_ptr<pfx::app::SceneRenderer> renderer;
};
Captured capture(const pfx::app::Scene& scene, int width, int height);

struct Rendered {
  std::vector<float> output;
  size_t passes = 0;
  nlohmann::json report;  // the effect's report_json members
  std::string error;      // why render failed (empty when it worked)
  std::vector<std::string> log;
};

class Rig {
 public:
  Rig();
  void set(const std::string& assignment);
  // No glFinish around passes: frames really queue up (the default times each pass with one).
  void chain_timing_off() { chain_->set_timing(pfx::host::Timing::OFF); }
  // Runs the chain over the captured frame (its frame and textures, which a test may replace).
  Rendered render(const Captured& captured);
  // Renders every frame into its own texture back to back, reading nothing back until all were
  // queued (so upload buffers are reused while the GPU may still read them).
  std::vector<std::vector<float>> render_queued(const std::vector<Captured*>& frames);
  // The plugin's reference of the captured inputs with the current settings.
  std::vector<float> reference(const Captured& captured, pfx_reference_kind kind);

 private:
  pfx::test::CollectedLog log_;
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  pfx::host::ParamStore params_;
  std::unique_ptr<pfx::host::Chain> chain_;
  const pfx_reference_factory* references_ = nullptr;
};

// A floor (20 m) and a box at the origin seen from (0, 3, 8); no lights, ambient 0.05.
pfx::app::Scene floor_and_box();
pfx_light point_light(float x, float y, float z, float r, float g, float b, float intensity, float range = 0);

// The stated tolerance of the GPU against the windowed reference (see lights_rig.cpp): the largest
// |gpu - reference| over the tolerance at that pixel (<= 1 passes).
double worst_error_ratio(const std::vector<float>& gpu, const std::vector<float>& reference);
// Fails the calling test naming the first pixel outside the tolerance.
void require_matches_reference(const Captured& captured, const std::vector<float>& gpu,
                               const std::vector<float>& reference);

// Brute force against the reference, then cpu8x4, tiled and clustered against brute force, bit for
// bit, and their list figures (check_list_figures). Returns the brute-force output. Without
// against_reference only the modes are compared (for inputs whose float decoding alone is
// outside the reference tolerance, e.g. hardware depth far from the near plane).
std::vector<float> check_modes(Rig& rig, const Captured& captured, bool against_reference = true);
// The report's list figures agree with each other: the mean is entries / lists, no list is longer
// than all of them or than the lights uploaded, the GPU's entries fit the CPU's bound and the index
// buffer without reading the total back, and the fill agreed with the count everywhere.
void check_list_figures(const nlohmann::json& report);
// Fails the calling test at the first pixel whose RGBA differs at all.
void require_identical(const std::vector<float>& a, const std::vector<float>& b, int width);

}  // namespace lights_test
