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
  std::string mode;
  double frame_scale = 1;  // the gaussian mode's tone scale
  int levels = 0;  // levels the pyramid used (0 when no pass ran)
  size_t passes = 0;
};

class Rig {
 public:
  Rig();
  void set(const std::string& assignment);
  Rendered render(const Picture& picture);
  pfx::host::Chain& chain() { return *chain_; }

 private:
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  pfx::host::ParamStore params_;
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
                       const pfx_bloom::ModelTrace& trace, double frame_scale);

// Every mode of the effect, as the mode parameter spells them.
inline const char* const kModes[] = {"chain", "chain13", "gaussian", "mgf"};

bool all_finite(const Picture& p);

}  // namespace bloom_test
