#include "pfx/host/frame_plan.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "host_layout.hpp"

namespace pfx::host {
namespace {

// The largest texture we ask for; GL 4.5 guarantees 16384.
constexpr uint32_t kMaxTargetSize = 16384;

struct FrameInputName {
  const char* name;
  uint32_t bit;
};
constexpr FrameInputName kFrameInputs[] = {
    {PFX_INPUT_NAME_COLOR, PFX_INPUT_COLOR},       {PFX_INPUT_NAME_DEPTH, PFX_INPUT_DEPTH},
    {PFX_INPUT_NAME_NORMAL, PFX_INPUT_NORMAL},     {PFX_INPUT_NAME_ALBEDO, PFX_INPUT_ALBEDO},
    {PFX_INPUT_NAME_EMISSIVE, PFX_INPUT_EMISSIVE},
};

const FrameInputName* find_frame_input(const std::string& name) {
  for (const auto& input : kFrameInputs)
    if (name == input.name) return &input;
  return nullptr;
}

uint32_t resolve_size(float scale, uint32_t frame) {
  double size = std::round(double(frame) * double(scale));
  return size < 1 ? 1u : static_cast<uint32_t>(size);
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
  auto fail = [&](const std::string& message) {
    *error = message;
    return false;
  };
  Declaration result;
  result.inputs = in.inputs;
  if ((in.target_count && !in.targets) || (in.pass_count && !in.passes))
    return fail("declaration has counts without arrays");
  // The plugin's arrays in this host's layout: a plugin built against another minor version steps
  // them by its own struct_size (core.h's growth rule).
  std::string problem;
  const std::vector<pfx_target_desc> targets =
      read_sized_array(in.targets, in.target_count, PFX_TARGET_DESC_MIN_SIZE, "target", &problem);
  if (!problem.empty()) return fail(problem);
  const std::vector<pfx_pass_desc> passes =
      read_sized_array(in.passes, in.pass_count, PFX_PASS_DESC_MIN_SIZE, "pass", &problem);
  if (!problem.empty()) return fail(problem);
  std::set<std::string> names;
  for (uint32_t i = 0; i < in.target_count; ++i) {
    const pfx_target_desc& t = targets[i];
    if (!t.name || !*t.name) return fail("target #" + std::to_string(i) + " has no name");
    std::string name = t.name;
    if (name == PFX_OUTPUT_NAME || find_frame_input(name))
      return fail("target '" + name + "' uses a reserved name");
    if (!names.insert(name).second) return fail("target '" + name + "' declared twice");
    if (format_bytes_per_pixel(t.format) == 0) return fail("target '" + name + "' has an unknown format");
    DeclaredTarget target;
    target.name = name;
    target.format = t.format;
    if (t.size_mode == PFX_SIZE_FIXED) {
      target.width = t.width;
      target.height = t.height;
    } else if (t.size_mode == PFX_SIZE_FRAME_SCALE) {
      if (!(t.scale_x > 0 && t.scale_y > 0) || !std::isfinite(t.scale_x) || !std::isfinite(t.scale_y))
        return fail("target '" + name + "' has a scale that is not a positive number");
      target.width = resolve_size(t.scale_x, frame_width);
      target.height = resolve_size(t.scale_y, frame_height);
    } else {
      return fail("target '" + name + "' has an unknown size mode");
    }
    if (target.width < 1 || target.height < 1 || target.width > kMaxTargetSize || target.height > kMaxTargetSize)
      return fail("target '" + name + "' is " + std::to_string(target.width) + "x" + std::to_string(target.height) +
                  ", outside 1.." + std::to_string(kMaxTargetSize));
    result.targets.push_back(target);
  }
  for (uint32_t i = 0; i < in.pass_count; ++i) {
    const pfx_pass_desc& p = passes[i];
    std::string label = "pass #" + std::to_string(i) + (p.name ? " '" + std::string(p.name) + "'" : "");
    if (p.kind != PFX_PASS_FULLSCREEN && p.kind != PFX_PASS_CUSTOM) return fail(label + ": unknown kind");
    if (p.blend > PFX_BLEND_ADD || p.load > PFX_LOAD_KEEP) return fail(label + ": unknown blend or load");
    if (!p.output && p.kind == PFX_PASS_FULLSCREEN) return fail(label + ": a full-screen pass needs an output");
    if (p.input_count && !p.inputs) return fail(label + ": input_count without inputs");
    if (p.input_count > PFX_MAX_PASS_INPUTS)
      return fail(label + ": " + std::to_string(p.input_count) + " inputs, more than the " +
                  std::to_string(PFX_MAX_PASS_INPUTS) + " a pass may name (PFX_MAX_PASS_INPUTS)");
    DeclaredPass pass;
    pass.name = p.name ? p.name : "pass" + std::to_string(i);
    pass.kind = p.kind;
    pass.output = p.output ? p.output : "";
    pass.blend = p.blend;
    pass.load = p.load;
    pass.user_tag = p.user_tag;
    for (uint32_t j = 0; j < p.input_count; ++j) {
      if (!p.inputs[j].name) return fail(label + ": input #" + std::to_string(j) + " has no name");
      if (p.inputs[j].filter > PFX_FILTER_NEAREST || p.inputs[j].wrap > PFX_WRAP_MIRRORED_REPEAT)
        return fail(label + ": input '" + p.inputs[j].name + "' has an unknown filter or wrap");
      pass.inputs.push_back({p.inputs[j].name, p.inputs[j].filter, p.inputs[j].wrap});
    }
    result.passes.push_back(std::move(pass));
  }
  *out = std::move(result);
  return true;
}

bool operator==(const Declaration& a, const Declaration& b) {
  if (a.inputs != b.inputs || a.targets.size() != b.targets.size() || a.passes.size() != b.passes.size()) return false;
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

bool plan_frame(const std::vector<PlanInput>& effects, uint32_t frame_width, uint32_t frame_height,
                uint32_t available_inputs, FramePlan* plan_out, std::string* error) {
  FramePlan plan;
  auto fail = [&](const std::string& message) {
    *error = message;
    return false;
  };
  // The colour every effect reads; the previous effect's output from the second effect on.
  ResourceRef chain_color;
  chain_color.kind = ResourceRef::FRAME_INPUT;
  chain_color.frame_input = PFX_INPUT_NAME_COLOR;

  for (size_t e = 0; e < effects.size(); ++e) {
    const Declaration& decl = *effects[e].declaration;
    const std::string effect_label = "effect '" + effects[e].effect_id + "'";
    const bool last_effect = e + 1 == effects.size();
    if (decl.passes.empty()) return fail(effect_label + ": planned with no passes");
    uint32_t missing = decl.inputs & ~available_inputs;
    if (missing) return fail(effect_label + " needs " + frame_input_names(missing) + ", which this frame does not provide");

    // Name -> resource for this effect: its targets, created when first written.
    std::map<std::string, int> local;
    std::map<std::string, const DeclaredTarget*> declared;
    for (const auto& t : decl.targets) declared[t.name] = &t;
    ResourceRef effect_output;
    bool output_written = false;

    for (size_t p = 0; p < decl.passes.size(); ++p) {
      const DeclaredPass& pass = decl.passes[p];
      const std::string pass_label = effect_label + " pass '" + pass.name + "'";
      const int global_index = static_cast<int>(plan.passes.size());
      PlannedPass planned;
      planned.effect = static_cast<int>(e);
      planned.pass = static_cast<int>(p);
      auto touch = [&](int resource) {
        PlannedResource& r = plan.resources[resource];
        r.last_pass = std::max(r.last_pass, global_index);
      };

      for (const auto& input : pass.inputs) {
        ResourceRef ref;
        if (input.name == PFX_INPUT_NAME_COLOR) {
          ref = chain_color;
        } else if (input.name == PFX_OUTPUT_NAME) {
          if (!output_written) return fail(pass_label + " reads 'output' before any pass writes it");
          ref = effect_output;
        } else if (const FrameInputName* frame_input = find_frame_input(input.name)) {
          if (!(available_inputs & frame_input->bit))
            return fail(effect_label + " needs input '" + input.name + "', which this frame does not provide");
          ref.kind = ResourceRef::FRAME_INPUT;
          ref.frame_input = input.name;
        } else if (declared.count(input.name)) {
          if (!local.count(input.name))
            return fail(pass_label + " reads target '" + input.name + "' before any pass writes it");
          ref.kind = ResourceRef::POOLED;
          ref.resource = local[input.name];
        } else {
          return fail(pass_label + " reads '" + input.name + "', which is neither a frame input nor a declared target");
        }
        if (ref.kind == ResourceRef::POOLED) touch(ref.resource);
        planned.inputs.push_back(ref);
      }

      if (!pass.output.empty()) {
        ResourceRef ref;
        bool first_write = false;
        if (pass.output == PFX_OUTPUT_NAME) {
          if (!output_written) {
            first_write = true;
            if (last_effect) {
              effect_output.kind = ResourceRef::CHAIN_OUTPUT;
            } else {
              PlannedResource r;
              r.effect = static_cast<int>(e);
              r.name = PFX_OUTPUT_NAME;
              r.format = PFX_FORMAT_RGBA16F;
              r.width = frame_width;
              r.height = frame_height;
              r.first_pass = r.last_pass = global_index;
              plan.resources.push_back(r);
              effect_output.kind = ResourceRef::POOLED;
              effect_output.resource = static_cast<int>(plan.resources.size()) - 1;
            }
            output_written = true;
          }
          ref = effect_output;
        } else if (declared.count(pass.output)) {
          if (!local.count(pass.output)) {
            first_write = true;
            const DeclaredTarget& t = *declared[pass.output];
            PlannedResource r;
            r.effect = static_cast<int>(e);
            r.name = t.name;
            r.format = t.format;
            r.width = t.width;
            r.height = t.height;
            r.first_pass = r.last_pass = global_index;
            plan.resources.push_back(r);
            local[pass.output] = static_cast<int>(plan.resources.size()) - 1;
          }
          ref.kind = ResourceRef::POOLED;
          ref.resource = local[pass.output];
        } else {
          return fail(pass_label + " writes '" + pass.output + "', which is not a declared target nor 'output'");
        }
        if (first_write && pass.load == PFX_LOAD_KEEP)
          return fail(pass_label + " keeps the contents of '" + pass.output + "', which no earlier pass wrote");
        // A pooled texture holds whatever its previous tenant left: adding into it needs a clear.
        if (first_write && pass.blend == PFX_BLEND_ADD && pass.load != PFX_LOAD_CLEAR)
          return fail(pass_label + " adds into '" + pass.output + "' on its first write without clearing it");
        for (const auto& input : planned.inputs)
          if (input.kind == ref.kind && ref.kind != ResourceRef::FRAME_INPUT && input.resource == ref.resource)
            return fail(pass_label + " reads and writes '" + pass.output + "' in the same pass");
        if (ref.kind == ResourceRef::POOLED) touch(ref.resource);
        planned.output = ref;
      }
      plan.passes.push_back(std::move(planned));
    }
    if (!output_written) return fail(effect_label + " never writes 'output'");
    chain_color = effect_output;
  }

  // The next effect's reads of "color" extended each output's lifetime through touch() above.
  // Pool: take resources in order of first use; each goes into a free slot of its exact format
  // and size whose previous tenant's last use came before this one's first, or a new slot.
  std::vector<int> order(plan.resources.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return plan.resources[a].first_pass < plan.resources[b].first_pass; });
  std::vector<int> slot_busy_until;
  for (int index : order) {
    PlannedResource& r = plan.resources[index];
    plan.unpooled_target_bytes += uint64_t(r.width) * r.height * format_bytes_per_pixel(r.format);
    for (size_t s = 0; s < plan.slots.size(); ++s) {
      const PoolSlot& slot = plan.slots[s];
      if (slot.format == r.format && slot.width == r.width && slot.height == r.height &&
          slot_busy_until[s] < r.first_pass) {
        r.slot = static_cast<int>(s);
        break;
      }
    }
    if (r.slot < 0) {
      plan.slots.push_back({r.format, r.width, r.height});
      slot_busy_until.push_back(-1);
      r.slot = static_cast<int>(plan.slots.size()) - 1;
    }
    slot_busy_until[r.slot] = r.last_pass;
  }
  for (const auto& slot : plan.slots) plan.peak_target_bytes += slot.bytes();
  *plan_out = std::move(plan);
  return true;
}

}  // namespace pfx::host
