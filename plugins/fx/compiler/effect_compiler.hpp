#pragma once
// The whole compiler in one call: front end, the effect's model, and GLSL for every pass of
// every technique. Nothing here throws; every problem is a diagnostic.
#include <memory>
#include <string>
#include <vector>

#include "codegen/glsl_generator.hpp"
#include "front_end.hpp"
#include "model/effect_model.hpp"

namespace pfx::fx {

struct CompiledEffect {
  std::unique_ptr<FrontEndResult> front;  // the tree the model points into, and the diagnostics
  EffectModel model;
  std::vector<std::vector<GeneratedPass>> passes;  // [technique][pass]

  bool ok() const { return front && front->ok(); }
  std::string errors() const { return front ? front->diagnostics.format_all() : std::string(); }
};

// generate_code = false stops after the model (what listing the effects needs).
std::unique_ptr<CompiledEffect> compile_effect(const std::string& path, const FrontEndOptions& options, bool generate_code,
                                               const FileReader& reader = read_file_from_disk);

}  // namespace pfx::fx
