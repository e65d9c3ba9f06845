// plan_frame (frame_plan.hpp) in three steps: each effect's passes are planned in chain order
// (where every pass reads and writes, checked against what was written before it), which records
// when each target is first and last used; then the targets are given pool slots by those
// lifetimes.
#include "pfx/host/frame_plan.hpp"

#include <algorithm>
#include <map>

#include "frame_inputs.hpp"

namespace pfx::host {
namespace {

// The frame's size and inputs, and the plan being filled.
struct PlanContext {
  uint32_t frame_width = 0, frame_height = 0;
  uint32_t available_inputs = 0;
  FramePlan* plan = nullptr;
};

// Plans the passes of one effect: resolves the names its passes read and write to frame inputs,
// the effect's own targets or the chain's colour, and extends each target's lifetime to the last
// pass that uses it.
class EffectPlanner {
 public:
  // `color` is what the effect reads as "color": the frame's, or the previous effect's output.
  // `codes_output`: an "output" between effects holds sRGB codes (RGBA8), not RGBA16F.
  EffectPlanner(const PlanContext& context, const PlanInput& effect, int effect_index, bool last_effect,
                const ResourceRef& color, bool codes_output);
  bool plan(std::string* error);
  // Where the effect wrote "output": the next effect's "color".
  const ResourceRef& output() const { return output_; }

 private:
  bool check_inputs(std::string* error) const;
  bool plan_pass(int pass_index, std::string* error);
  bool resolve_input(const DeclaredPass& pass, const DeclaredInput& input, ResourceRef* ref, std::string* error) const;
  // *first_write: no earlier pass wrote it.
  bool resolve_output(const DeclaredPass& pass, int global_pass, ResourceRef* ref, bool* first_write,
                      std::string* error);
  bool check_output(const DeclaredPass& pass, const PlannedPass& planned, const ResourceRef& ref, bool first_write,
                    std::string* error) const;
  int add_resource(const std::string& name, pfx_format format, uint32_t width, uint32_t height, int global_pass);
  void touch(const ResourceRef& ref, int global_pass);
  // Messages: built only when something is wrong.
  bool fail(std::string* error, const std::string& what) const;
  bool fail_pass(std::string* error, const DeclaredPass& pass, const std::string& what) const;

  const PlanContext& context_;
  const PlanInput& effect_;
  const Declaration& declaration_;
  int effect_index_;
  bool last_effect_;
  bool codes_output_;
  ResourceRef color_;
  std::map<std::string, const DeclaredTarget*> declared_;
  std::map<std::string, int> written_;  // target name -> resource, from its first write on
  ResourceRef output_;
  bool output_written_ = false;
};

EffectPlanner::EffectPlanner(const PlanContext& context, const PlanInput& effect, int effect_index, bool last_effect,
                             const ResourceRef& color, bool codes_output)
    : context_(context),
      effect_(effect),
      declaration_(*effect.declaration),
      effect_index_(effect_index),
      last_effect_(last_effect),
      codes_output_(codes_output),
      color_(color) {
  for (const auto& target : declaration_.targets) declared_[target.name] = &target;
}

bool EffectPlanner::fail(std::string* error, const std::string& what) const {
  *error = "effect '" + effect_.effect_id + "'" + what;
  return false;
}

bool EffectPlanner::fail_pass(std::string* error, const DeclaredPass& pass, const std::string& what) const {
  return fail(error, " pass '" + pass.name + "' " + what);
}

bool EffectPlanner::plan(std::string* error) {
  if (!check_inputs(error)) return false;
  for (size_t p = 0; p < declaration_.passes.size(); ++p)
    if (!plan_pass(static_cast<int>(p), error)) return false;
  if (!output_written_) return fail(error, " never writes 'output'");
  return true;
}

bool EffectPlanner::check_inputs(std::string* error) const {
  if (declaration_.passes.empty()) return fail(error, ": planned with no passes");
  const uint32_t missing = declaration_.inputs & ~context_.available_inputs;
  if (missing) return fail(error, " needs " + frame_input_names(missing) + ", which this frame does not provide");
  return true;
}

bool EffectPlanner::plan_pass(int pass_index, std::string* error) {
  const DeclaredPass& pass = declaration_.passes[pass_index];
  const int global_pass = static_cast<int>(context_.plan->passes.size());
  PlannedPass planned;
  planned.effect = effect_index_;
  planned.pass = pass_index;
  planned.display_referred = declaration_.display_referred();
  for (const auto& input : pass.inputs) {
    ResourceRef ref;
    if (!resolve_input(pass, input, &ref, error)) return false;
    touch(ref, global_pass);
    planned.inputs.push_back(ref);
  }
  if (!pass.output.empty()) {
    bool first_write = false;
    if (!resolve_output(pass, global_pass, &planned.output, &first_write, error) ||
        !check_output(pass, planned, planned.output, first_write, error))
      return false;
    touch(planned.output, global_pass);
  }
  context_.plan->passes.push_back(std::move(planned));
  return true;
}

bool EffectPlanner::resolve_input(const DeclaredPass& pass, const DeclaredInput& input, ResourceRef* ref,
                                  std::string* error) const {
  if (input.name == PFX_INPUT_NAME_COLOR) {
    *ref = color_;
  } else if (input.name == PFX_OUTPUT_NAME) {
    if (!output_written_) return fail_pass(error, pass, "reads 'output' before any pass writes it");
    *ref = output_;
  } else if (const FrameInputName* frame_input = find_frame_input(input.name)) {
    if (!(context_.available_inputs & frame_input->bit))
      return fail(error, " needs input '" + input.name + "', which this frame does not provide");
    ref->kind = ResourceRef::FRAME_INPUT;
    ref->frame_input = input.name;
  } else if (declared_.count(input.name)) {
    auto written = written_.find(input.name);
    if (written == written_.end())
      return fail_pass(error, pass, "reads target '" + input.name + "' before any pass writes it");
    ref->kind = ResourceRef::POOLED;
    ref->resource = written->second;
  } else {
    return fail_pass(error, pass, "reads '" + input.name + "', which is neither a frame input nor a declared target");
  }
  return true;
}

bool EffectPlanner::resolve_output(const DeclaredPass& pass, int global_pass, ResourceRef* ref, bool* first_write,
                                   std::string* error) {
  if (pass.output == PFX_OUTPUT_NAME) {
    *first_write = !output_written_;
    if (*first_write) {
      // The last effect writes the chain's output texture; the others an intermediate the next reads.
      output_.kind = last_effect_ ? ResourceRef::CHAIN_OUTPUT : ResourceRef::POOLED;
      if (!last_effect_) {
        output_.resource = add_resource(PFX_OUTPUT_NAME, codes_output_ ? PFX_FORMAT_RGBA8 : PFX_FORMAT_RGBA16F,
                                        context_.frame_width, context_.frame_height, global_pass);
        context_.plan->resources[output_.resource].display_codes = codes_output_;
      }
      output_written_ = true;
    }
    *ref = output_;
    return true;
  }
  auto declared = declared_.find(pass.output);
  if (declared == declared_.end())
    return fail_pass(error, pass, "writes '" + pass.output + "', which is not a declared target nor 'output'");
  auto written = written_.find(pass.output);
  *first_write = written == written_.end();
  if (*first_write) {
    const DeclaredTarget& t = *declared->second;
    written = written_.emplace(pass.output, add_resource(t.name, t.format, t.width, t.height, global_pass)).first;
  }
  ref->kind = ResourceRef::POOLED;
  ref->resource = written->second;
  return true;
}

bool EffectPlanner::check_output(const DeclaredPass& pass, const PlannedPass& planned, const ResourceRef& ref,
                                 bool first_write, std::string* error) const {
  if (first_write && pass.load == PFX_LOAD_KEEP)
    return fail_pass(error, pass, "keeps the contents of '" + pass.output + "', which no earlier pass wrote");
  // A pooled texture holds whatever its previous tenant left: adding into it needs a clear.
  if (first_write && pass.blend == PFX_BLEND_ADD && pass.load != PFX_LOAD_CLEAR)
    return fail_pass(error, pass, "adds into '" + pass.output + "' on its first write without clearing it");
  for (const auto& input : planned.inputs)
    if (input.kind == ref.kind && ref.kind != ResourceRef::FRAME_INPUT && input.resource == ref.resource)
      return fail_pass(error, pass, "reads and writes '" + pass.output + "' in the same pass");
  return true;
}

int EffectPlanner::add_resource(const std::string& name, pfx_format format, uint32_t width, uint32_t height,
                                int global_pass) {
  PlannedResource r;
  r.effect = effect_index_;
  r.name = name;
  r.format = format;
  r.width = width;
  r.height = height;
  r.first_pass = r.last_pass = global_pass;
  context_.plan->resources.push_back(r);
  return static_cast<int>(context_.plan->resources.size()) - 1;
}

void EffectPlanner::touch(const ResourceRef& ref, int global_pass) {
  if (ref.kind != ResourceRef::POOLED) return;
  PlannedResource& r = context_.plan->resources[ref.resource];
  r.last_pass = std::max(r.last_pass, global_pass);
}

// Takes the resources in order of first use; each goes into a free slot of its exact format and
// size whose previous tenant's last use came before this one's first, or a new slot.
void assign_pool_slots(FramePlan* plan) {
  std::vector<int> order(plan->resources.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return plan->resources[a].first_pass < plan->resources[b].first_pass; });
  std::vector<int> slot_busy_until;
  for (int index : order) {
    PlannedResource& r = plan->resources[index];
    plan->unpooled_target_bytes += uint64_t(r.width) * r.height * format_bytes_per_pixel(r.format);
    for (size_t s = 0; s < plan->slots.size() && r.slot < 0; ++s) {
      const PoolSlot& slot = plan->slots[s];
      if (slot.format == r.format && slot.width == r.width && slot.height == r.height &&
          slot_busy_until[s] < r.first_pass)
        r.slot = static_cast<int>(s);
    }
    if (r.slot < 0) {
      plan->slots.push_back({r.format, r.width, r.height});
      slot_busy_until.push_back(-1);
      r.slot = static_cast<int>(plan->slots.size()) - 1;
    }
    slot_busy_until[r.slot] = r.last_pass;
  }
  for (const auto& slot : plan->slots) plan->peak_target_bytes += slot.bytes();
}

// Whether the "output" between `writer` and `reader` holds sRGB codes: a display-referred writer
// writes them; a linear writer does when the reader wants them and the writer can draw into an sRGB
// view (the encoding folded into its draw).
bool output_holds_codes(const Declaration& writer, const Declaration& reader) {
  return writer.display_referred() || (reader.display_referred() && writer.samples_and_draws());
}

// The conversion between two neighbours that output_holds_codes could not fold: a linear reader
// that cannot sample codes, or a linear writer that could not draw them.
Conversion conversion_between(const Declaration& writer, const Declaration& reader) {
  if (writer.display_referred() && !reader.display_referred() && !reader.samples_and_draws())
    return Conversion::TO_LINEAR;
  if (!writer.display_referred() && reader.display_referred() && !writer.samples_and_draws())
    return Conversion::TO_DISPLAY;
  return Conversion::NONE;
}

// A conversion pass of the chain from `color` into a new intermediate of the other encoding, which
// effect `reader` then reads as "color".
ResourceRef plan_conversion(Conversion conversion, int reader, const ResourceRef& color, const PlanContext& context) {
  FramePlan& plan = *context.plan;
  const int global_pass = static_cast<int>(plan.passes.size());
  plan.resources[color.resource].last_pass = global_pass;  // `color` is an "output" between effects
  PlannedResource r;
  r.effect = reader;
  r.name = conversion == Conversion::TO_DISPLAY ? "color as sRGB codes" : "color as linear light";
  r.format = conversion == Conversion::TO_DISPLAY ? PFX_FORMAT_RGBA8 : PFX_FORMAT_RGBA16F;
  r.display_codes = conversion == Conversion::TO_DISPLAY;
  r.width = context.frame_width;
  r.height = context.frame_height;
  r.first_pass = r.last_pass = global_pass;
  plan.resources.push_back(r);
  PlannedPass pass;
  pass.effect = reader;
  pass.pass = -1;
  pass.conversion = conversion;
  pass.inputs.push_back(color);
  pass.output.kind = ResourceRef::POOLED;
  pass.output.resource = static_cast<int>(plan.resources.size()) - 1;
  plan.passes.push_back(pass);
  return pass.output;
}

}  // namespace

bool plan_frame(const std::vector<PlanInput>& effects, uint32_t frame_width, uint32_t frame_height,
                uint32_t available_inputs, FramePlan* plan_out, std::string* error) {
  FramePlan plan;
  const PlanContext context{frame_width, frame_height, available_inputs, &plan};
  // The colour every effect reads: the frame's, then the previous effect's output, whose lifetime
  // that read extends.
  ResourceRef color;
  color.kind = ResourceRef::FRAME_INPUT;
  color.frame_input = PFX_INPUT_NAME_COLOR;
  for (size_t e = 0; e < effects.size(); ++e) {
    const bool last = e + 1 == effects.size();
    const Conversion conversion =
        e == 0 ? Conversion::NONE : conversion_between(*effects[e - 1].declaration, *effects[e].declaration);
    if (conversion != Conversion::NONE) color = plan_conversion(conversion, static_cast<int>(e), color, context);
    const bool codes_output = !last && output_holds_codes(*effects[e].declaration, *effects[e + 1].declaration);
    EffectPlanner effect(context, effects[e], static_cast<int>(e), last, color, codes_output);
    if (!effect.plan(error)) return false;
    color = effect.output();
  }
  assign_pool_slots(&plan);
  *plan_out = std::move(plan);
  return true;
}

}  // namespace pfx::host
