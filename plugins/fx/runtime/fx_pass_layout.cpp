#include "fx_pass_layout.hpp"

#include <cstring>

#include <pfx/cpp/srgb_glsl.hpp>

#include "fx_programs.hpp"

namespace pfx_fx {
namespace {

using pfx::fx::GeneratedPass;
using pfx::fx::PassInfo;

bool writes_back_buffer(const PassInfo& pass) { return !pass.compute_shader && pass.render_target_count == 0; }

bool samples_back_buffer(const pfx::fx::EffectModel& model, const GeneratedPass& generated) {
  for (int s : generated.sampler_units) {
    const int t = model.samplers[static_cast<std::size_t>(s)].texture;
    if (t >= 0 && model.textures[static_cast<std::size_t>(t)].semantic == pfx::fx::TextureSemantic::kColor) return true;
  }
  return false;
}

// Whether a sampler reads the back buffer decoded (SRGBTexture = true).
bool samples_back_buffer_as_srgb(const pfx::fx::EffectModel& model) {
  for (const pfx::fx::SamplerInfo& s : model.samplers)
    if (s.srgb && s.texture >= 0 && model.textures[static_cast<std::size_t>(s.texture)].semantic == pfx::fx::TextureSemantic::kColor)
      return true;
  return false;
}

// Whether the technique can start on the host's codes: the first pass that writes the back buffer
// writes all of it (one that leaves pixels starts from a copy of the picture, and the effect
// promised only to sample the frame).
bool can_sample_frame(const pfx::fx::TechniqueInfo& technique, const std::vector<GeneratedPass>& generated) {
  for (std::size_t i = 0; i < technique.passes.size(); ++i)
    if (writes_back_buffer(technique.passes[i])) return pfx::fx::covers_back_buffer(technique.passes[i], generated[i].may_discard);
  return true;
}

// The technique's last back-buffer pass, when it can draw into the host's output: it writes every
// pixel (the output does not hold the picture to keep), and no later pass samples the back buffer
// (an output is drawn into, never sampled).
int find_output_pass(const pfx::fx::EffectModel& model, const pfx::fx::TechniqueInfo& technique,
                     const std::vector<GeneratedPass>& generated) {
  int last = -1;
  for (std::size_t i = 0; i < technique.passes.size(); ++i)
    if (writes_back_buffer(technique.passes[i])) last = static_cast<int>(i);
  if (last < 0) return -1;
  const PassInfo& pass = technique.passes[static_cast<std::size_t>(last)];
  const GeneratedPass& g = generated[static_cast<std::size_t>(last)];
  if (!pfx::fx::covers_back_buffer(pass, g.may_discard) || g.fragment.find("pfx_target_0") == std::string::npos) return -1;
  for (std::size_t j = static_cast<std::size_t>(last) + 1; j < technique.passes.size(); ++j)
    if (samples_back_buffer(model, generated[j])) return -1;
  return last;
}

}  // namespace

FxPassLayout plan_pass_layout(const pfx::fx::CompiledEffect& compiled, int technique, bool display_referred) {
  FxPassLayout layout;
  layout.display_referred = display_referred;
  if (!display_referred) return layout;
  const pfx::fx::TechniqueInfo& info = compiled.model.techniques[static_cast<std::size_t>(technique)];
  const auto& generated = compiled.passes[static_cast<std::size_t>(technique)];
  layout.samples_frame = can_sample_frame(info, generated);
  layout.srgb_frame_view = layout.samples_frame && samples_back_buffer_as_srgb(compiled.model);
  layout.output_pass = find_output_pass(compiled.model, info, generated);
  return layout;
}

std::string with_frame_alpha(const std::string& fragment, std::size_t unit, bool encode_srgb) {
  // The generated entry point is the shader's one main(); it becomes a function main() calls.
  const char* const entry = "void main() {";
  const std::size_t at = fragment.rfind(entry);
  if (at == std::string::npos) return fragment;
  std::string out = fragment.substr(0, at) + "void pfx_technique_main() {" + fragment.substr(at + std::strlen(entry));
  if (encode_srgb) out += pfx::gl::srgb_glsl_functions();
  out += "layout(binding = " + std::to_string(unit) + ") uniform sampler2D pfx_frame_alpha;\n"
         "void main() {\n"
         "  pfx_technique_main();\n";
  if (encode_srgb)
    out += "  vec3 linear = clamp(mix(pfx_target_0.rgb, vec3(0.0), isnan(pfx_target_0.rgb)), 0.0, 1.0);\n"
           "  pfx_target_0.rgb = pfx_srgb_encode(linear);\n";
  return out + "  pfx_target_0.a = texelFetch(pfx_frame_alpha, ivec2(gl_FragCoord.xy), 0).a;\n}\n";
}

}  // namespace pfx_fx
