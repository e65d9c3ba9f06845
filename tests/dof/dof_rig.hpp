// What the dof GL tests share: a chain holding the dof plugin (loaded from its build path), frames
// of colour and depth given bottom-first (as the GPU and the CPU references see them), rendering
// through libpfxhost with the depth as an R32F texture or a real GL depth texture, and the plugin's
// CPU references of the same frame and settings.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "gl_test_support.hpp"

namespace dof_test {

// RGBA floats and one depth value per pixel, rows bottom first.
struct Frame {
  int width = 0, height = 0;
  std::vector<float> rgba;
  std::vector<float> depth;  // as `encoding` says
  pfx_depth_encoding encoding = PFX_DEPTH_LINEAR;
  double fovy_degrees = 45, near_plane = 0.1, far_plane = 1000;
  Frame() = default;
  Frame(int w, int h);
  float* at(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const float* at(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  float& z(int x, int y) { return depth[static_cast<size_t>(y) * width + x]; }
  pfx_frame frame() const;
};

// A textured backdrop at 20 m, a square at 1.5 m, a strip at 5 m and a few bright points, all values
// exact in half floats: every mode has near, far and in-focus regions and edges between them.
Frame scene(int width, int height, double focus_hint = 5.0);

struct Rendered {
  Frame input;                // what the GPU saw (colour read back from its RGBA16F texture)
  std::vector<float> output;  // RGBA, bottom first
  std::vector<float> model;   // PFX_REFERENCE_MODEL of the same input and settings (empty if none)
  size_t passes = 0;
};

enum class DepthTexture { R32F, DEPTH_COMPONENT32F };

class Rig {
 public:
  Rig();
  void set(const std::string& assignment);
  // Fails the calling test with the host's message if the frame does not render.
  Rendered render(const Frame& frame, DepthTexture depth_texture = DepthTexture::R32F);
  // False with *error when the chain refuses the frame.
  bool try_render(const Frame& frame, std::string* error, bool with_depth = true);
  const pfx_value* values() const { return params_.values("dof"); }
  pfx::host::Chain& chain() { return *chain_; }
  const pfx_reference_factory* references() const { return references_; }
  const pfx::test::CollectedLog& log() const { return log_; }

 private:
  pfx::test::CollectedLog log_;
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  pfx::host::ParamStore params_;
  std::unique_ptr<pfx::host::Chain> chain_;
  const pfx_reference_factory* references_ = nullptr;
};

// One rig for the test process (its programs are compiled once), reset to the tests' common
// settings: focus 5 m, f/0.1 (small frames need a wide aperture to blur visibly), max CoC 32 px,
// autofocus off at the centre, 32 samples at half resolution, 36 mm sensor, non-finite pixels black
// (the default); then `mode`.
Rig& shared_rig(const std::string& mode);

// The reference of `kind` for a frame and the rig's current settings; REQUIREs that it succeeds.
std::vector<float> reference(const Rig& rig, const Frame& frame, pfx_reference_kind kind);

bool all_finite(const std::vector<float>& rgba);

// Largest |a - b| over RGB.
double max_difference(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace dof_test
