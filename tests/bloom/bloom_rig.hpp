// What the bloom GL tests share: a chain holding the bloom plugin (loaded from its build path),
// rendering of images given bottom-first (as the GPU and the CPU reference see them), the CPU model
// of the same settings, and the stated GPU-against-model tolerance.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "reference/bloom_model.hpp"

namespace bloom_test {

// RGBA floats, rows bottom first.
struct Picture {
  int width = 0, height = 0;
  std::vector<float> rgba;
  Picture() = default;
  Picture(int w, int h, float r, float g, float b, float a = 1.0f);
  float* at(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const float* at(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

// A dim gradient with a few bright spots of different sizes and colours, all values exact in half.
Picture scene(int width, int height);

struct Rendered {
  Picture input;   // what the GPU's RGBA16F colour texture holds (the upload read back)
  Picture output;  // the chain's output read back
  Picture model;   // PFX_REFERENCE_MODEL of the same input and settings
  pfx_bloom::ModelTrace trace;  // what the model saw of the GPU's rounding
  std::string mode;  // the bloom mode, or "glare"
  double frame_scale = 1;  // the gaussian mode's tone scale
  int levels = 0;  // levels the pyramid used (0 when no pass ran)
  int nonfinite = pfx_bloom::NONFINITE_ZERO;  // what a non-finite pixel counted as
  size_t passes = 0;
};

// A chain holding one effect of the bloom plugin ("bloom" or "glare").
class Rig {
 public:
  explicit Rig(const std::string& effect = "bloom");
  // "param=value" for this rig's effect, or a full "effect.param=value".
  void set(const std::string& assignment);
  Rendered render(const Picture& picture);
  // The chain's output alone (no model, no read-back of the input): for sweeps of many frames.
  Picture render_output(const Picture& picture);
  pfx::host::Chain& chain() { return *chain_; }
  const std::string& effect() const { return effect_; }
  // The effect's current parameter values, as the plugin receives them.
  const pfx_value* values() const { return params_->values(effect_); }

 private:
  std::string effect_;
  // Behind pointers, so a moved Rig keeps what the chain refers to.
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  std::unique_ptr<pfx::host::ParamStore> params_ = std::make_unique<pfx::host::ParamStore>();
  std::unique_ptr<pfx::host::Chain> chain_;
  const pfx_reference_factory* references_ = nullptr;
};

// The GPU output must equal the model within what its rounding allows, per pixel and in the RMS
// sense; see bloom_rig.cpp for the derivations. Fails the calling test naming the first pixel outside the tolerance.
void require_matches_model(const Rendered& r);
// The largest |output - model| over the tolerance at that pixel (<= 1 passes).
double worst_error_ratio(const Picture& output, const Picture& model, const pfx_bloom::ModelTrace& trace);
// rms(gpu - model) over its allowed value (S * 2^-10 + 2^-7) * rms(bloom) (<= 1 passes).
double rms_error_ratio(const Picture& output, const Picture& model, const Picture& input,
                       const pfx_bloom::ModelTrace& trace, double frame_scale,
                       int nonfinite = pfx_bloom::NONFINITE_ZERO);

// Every mode of the bloom effect, as the mode parameter spells them.
inline const char* const kModes[] = {"chain", "chain13", "gaussian", "mgf"};
// The bloom modes and the glare effect: what the hard cases run on.
inline const char* const kVariants[] = {"chain", "chain13", "gaussian", "mgf", "glare"};

// A rig for a variant: the bloom effect in that mode, or the glare effect.
Rig rig_for(const char* variant);

bool all_finite(const Picture& p);

}  // namespace bloom_test
