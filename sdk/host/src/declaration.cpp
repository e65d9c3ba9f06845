// A plugin's declaration copied into the host's own types and checked (frame_plan.hpp), before
// anything is planned from it.
#include <cmath>
#include <set>

#include "frame_inputs.hpp"
#include "host_layout.hpp"
#include "pfx/host/frame_plan.hpp"

namespace pfx::host {
namespace {

// The largest texture we ask for; GL 4.5 guarantees 16384.
constexpr uint32_t kMaxTargetSize = 16384;

uint32_t resolve_size(float scale, uint32_t frame) {
  double size = std::round(double(frame) * double(scale));
  return size < 1 ? 1u : static_cast<uint32_t>(size);
}

bool fail(std::string* error, const std::string& message) {
  *error = message;
  return false;
}

// Target `index` of the declaration, its size resolved against the frame; `names` are those of the
// targets before it.
bool copy_target(const pfx_target_desc& t, uint32_t index, uint32_t frame_width, uint32_t frame_height,
                 std::set<std::string>* names, DeclaredTarget* out, std::string* error) {
  if (!t.name || !*t.name) return fail(error, "target #" + std::to_string(index) + " has no name");
  const std::string name = t.name;
  if (name == PFX_OUTPUT_NAME || find_frame_input(name)) return fail(error, "target '" + name + "' uses a reserved name");
  if (!names->insert(name).second) return fail(error, "target '" + name + "' declared twice");
  if (format_bytes_per_pixel(t.format) == 0) return fail(error, "target '" + name + "' has an unknown format");
  out->name = name;
  out->format = t.format;
  if (t.size_mode == PFX_SIZE_FIXED) {
    out->width = t.width;
    out->height = t.height;
  } else if (t.size_mode == PFX_SIZE_FRAME_SCALE) {
    if (!(t.scale_x > 0 && t.scale_y > 0) || !std::isfinite(t.scale_x) || !std::isfinite(t.scale_y))
      return fail(error, "target '" + name + "' has a scale that is not a positive number");
    out->width = resolve_size(t.scale_x, frame_width);
    out->height = resolve_size(t.scale_y, frame_height);
  } else {
    return fail(error, "target '" + name + "' has an unknown size mode");
  }
  if (out->width < 1 || out->height < 1 || out->width > kMaxTargetSize || out->height > kMaxTargetSize)
    return fail(error, "target '" + name + "' is " + std::to_string(out->width) + "x" + std::to_string(out->height) +
                           ", outside 1.." + std::to_string(kMaxTargetSize));
  return true;
}

// Pass `index` of the declaration; unnamed passes are called "pass<index>".
bool copy_pass(const pfx_pass_desc& p, uint32_t index, DeclaredPass* out, std::string* error) {
  auto fail_pass = [&](const std::string& what) {
    return fail(error, "pass #" + std::to_string(index) + (p.name ? " '" + std::string(p.name) + "'" : "") + ": " + what);
  };
  if (p.kind != PFX_PASS_FULLSCREEN && p.kind != PFX_PASS_CUSTOM) return fail_pass("unknown kind");
  if (p.blend > PFX_BLEND_ADD || p.load > PFX_LOAD_KEEP) return fail_pass("unknown blend or load");
  if (!p.output && p.kind == PFX_PASS_FULLSCREEN) return fail_pass("a full-screen pass needs an output");
  if (p.input_count && !p.inputs) return fail_pass("input_count without inputs");
  if (p.input_count > PFX_MAX_PASS_INPUTS)
    return fail_pass(std::to_string(p.input_count) + " inputs, more than the " + std::to_string(PFX_MAX_PASS_INPUTS) +
                     " a pass may name (PFX_MAX_PASS_INPUTS)");
  out->name = p.name ? p.name : "pass" + std::to_string(index);
  out->kind = p.kind;
  out->output = p.output ? p.output : "";
  out->blend = p.blend;
  out->load = p.load;
  out->user_tag = p.user_tag;
  for (uint32_t j = 0; j < p.input_count; ++j) {
    const pfx_pass_input& input = p.inputs[j];
    if (!input.name) return fail_pass("input #" + std::to_string(j) + " has no name");
    if (input.filter > PFX_FILTER_NEAREST || input.wrap > PFX_WRAP_MIRRORED_REPEAT)
      return fail_pass("input '" + std::string(input.name) + "' has an unknown filter or wrap");
    out->inputs.push_back({input.name, input.filter, input.wrap});
  }
  return true;
}

}  // namespace

std::string frame_input_names(uint32_t bits) {
  std::string names;
  const char* all[] = {"color", "depth", "normal", "albedo", "emissive", "lights"};
  for (int i = 0; i < 6; ++i)
    if (bits & (1u << i)) names += (names.empty() ? "" : ", ") + std::string(all[i]);
  return names;
}

uint32_t declared_frame_inputs(const Declaration& declaration) {
  uint32_t bits = declaration.inputs;
  for (const auto& pass : declaration.passes)
    for (const auto& input : pass.inputs)
      if (const FrameInputName* frame_input = find_frame_input(input.name)) bits |= frame_input->bit;
  return bits;
}

uint64_t format_bytes_per_pixel(pfx_format format) {
  switch (format) {
    case PFX_FORMAT_RGBA16F: return 8;
    case PFX_FORMAT_RGBA32F: return 16;
    case PFX_FORMAT_R16F: return 2;
    case PFX_FORMAT_R32F: return 4;
    case PFX_FORMAT_RG16F: return 4;
    case PFX_FORMAT_RG32F: return 8;
    case PFX_FORMAT_RGBA8: return 4;
    default: return 0;
  }
}

bool copy_declaration(const pfx_declaration& in, uint32_t frame_width, uint32_t frame_height, Declaration* out,
                      std::string* error) {
  Declaration result;
  result.inputs = in.inputs;
  result.flags = in.flags;  // the host handed the plugin a struct with the field, zeroed
  if ((in.target_count && !in.targets) || (in.pass_count && !in.passes))
    return fail(error, "declaration has counts without arrays");
  // The plugin's arrays in this host's layout: a plugin built against another minor version steps
  // them by its own struct_size (core.h's growth rule).
  std::string problem;
  const std::vector<pfx_target_desc> targets =
      read_sized_array(in.targets, in.target_count, PFX_TARGET_DESC_MIN_SIZE, "target", &problem);
  if (!problem.empty()) return fail(error, problem);
  const std::vector<pfx_pass_desc> passes =
      read_sized_array(in.passes, in.pass_count, PFX_PASS_DESC_MIN_SIZE, "pass", &problem);
  if (!problem.empty()) return fail(error, problem);
  std::set<std::string> names;
  result.targets.resize(in.target_count);
  for (uint32_t i = 0; i < in.target_count; ++i)
    if (!copy_target(targets[i], i, frame_width, frame_height, &names, &result.targets[i], error)) return false;
  result.passes.resize(in.pass_count);
  for (uint32_t i = 0; i < in.pass_count; ++i)
    if (!copy_pass(passes[i], i, &result.passes[i], error)) return false;
  *out = std::move(result);
  return true;
}

bool operator==(const Declaration& a, const Declaration& b) {
  if (a.inputs != b.inputs || a.flags != b.flags || a.targets.size() != b.targets.size() || a.passes.size() != b.passes.size()) return false;
  for (size_t i = 0; i < a.targets.size(); ++i) {
    const auto &x = a.targets[i], &y = b.targets[i];
    if (x.name != y.name || x.format != y.format || x.width != y.width || x.height != y.height) return false;
  }
  for (size_t i = 0; i < a.passes.size(); ++i) {
    const auto &x = a.passes[i], &y = b.passes[i];
    if (x.name != y.name || x.kind != y.kind || x.output != y.output || x.inputs != y.inputs || x.blend != y.blend ||
        x.load != y.load || x.user_tag != y.user_tag)
      return false;
  }
  return true;
}

}  // namespace pfx::host
