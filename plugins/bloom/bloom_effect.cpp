// The "bloom" effect on the GPU: create compiles every mode's programs once (so switching modes is
// a parameter change, never a reload), declare asks for the chosen mode's targets and passes, and
// run_pass hands each pass to its mode (bloom_chain_passes.cpp, bloom_blur_passes.cpp).
#include "bloom_effect.hpp"

#include <cstdio>
#include <new>
#include <string>

#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include "bloom_gl.hpp"
#include "bloom_passes.hpp"
#include "bloom_shaders.hpp"

namespace pfx_bloom {
namespace {

struct Instance {
  GLuint programs[PROGRAM_COUNT] = {};
  DeclarationBuilder declaration;  // what declare hands the host; valid until the next declare
  char report[160] = "";
  int last_mode = MODE_CHAIN;
  LevelPlan last_plan;
};

void destroy(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst) return;
  for (GLuint program : inst->programs) glDeleteProgram(program);  // 0 is a silent no-op
  delete inst;
}

const ProgramSpec kPrograms[PROGRAM_COUNT] = {
    {"bright", shaders::bright},         {"down", shaders::down},
    {"up", shaders::up},                 {"composite", shaders::composite},
    {"bright13", shaders::bright13},     {"down13", shaders::down13},
    {"box_bright", shaders::box_bright}, {"blur", shaders::blur},
    {"gaussian_composite", shaders::gaussian_composite}, {"mgf_composite", shaders::mgf_composite}};

pfx_status create(const pfx_host* host, void** out) {
  if (!pfx::plugin::usable_host(host) || !out) return PFX_INVALID_ARGUMENT;
  if (!load_gl(host)) return PFX_GL_ERROR;
  Instance* inst = new (std::nothrow) Instance;
  if (!inst) return PFX_OUT_OF_MEMORY;
  if (!build_programs(host, kPrograms, PROGRAM_COUNT, inst->programs)) {
    destroy(inst);
    return PFX_GL_ERROR;
  }
  *out = inst;
  return PFX_OK;
}

pfx_status declare(void* self, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !pfx::plugin::usable_declare_arguments(frame, params, out)) return PFX_INVALID_ARGUMENT;
  const Settings settings = settings_from(params);
  inst->declaration.clear();
  inst->last_mode = settings.mode;
  inst->last_plan = LevelPlan{};
  if (settings.is_noop()) return PFX_OK;  // no passes: the host skips the effect
  const LevelPlan plan = plan_for(settings, frame->width, frame->height);
  inst->last_plan = plan;
  switch (settings.mode) {
    case MODE_CHAIN:
    case MODE_CHAIN13: declare_chain(settings, plan, inst->declaration); break;
    case MODE_GAUSSIAN: declare_gaussian(settings, plan, inst->declaration); break;
    case MODE_MGF: declare_mgf(settings, plan, inst->declaration); break;
    default: return PFX_INVALID_ARGUMENT;
  }
  // Every pass samples its inputs and draws its output.
  inst->declaration.samples_and_draws();
  return inst->declaration.finish(out);
}

pfx_status run_pass(void* self, const pfx_pass_context* context) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !context || context->struct_size < PFX_PASS_CONTEXT_MIN_SIZE) return PFX_INVALID_ARGUMENT;
  const Settings s = settings_from(context->params);
  const LevelPlan plan = plan_for(s, context->frame->width, context->frame->height);
  if (s.mode == MODE_CHAIN || s.mode == MODE_CHAIN13)
    run_chain_pass(inst->programs, s, plan, *context);
  else
    run_blur_pass(inst->programs, s, plan, *context);
  return PFX_OK;
}

const char* report_json(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  const LevelPlan& plan = inst->last_plan;
  const int last = plan.count > 0 ? plan.count - 1 : 0;
  std::snprintf(inst->report, sizeof inst->report, "\"mode\": \"%s\", \"levels\": %d, \"smallest_level\": \"%dx%d\"",
                mode_name(inst->last_mode), plan.count, plan.width[last], plan.height[last]);
  return inst->report;
}

}  // namespace

const pfx_effect_desc kBloomEffect =
    pfx::desc::effect("bloom")
        .label("Bloom")
        .description(
            "Light above a threshold spreads into its surroundings: a half-size pyramid in the style of Call "
            "of Duty: Advanced Warfare (chain), its 13-tap variant (chain13), a separable Gaussian (gaussian) "
            "or Kawase's multi-Gaussian (mgf).")
        .params(kParams, PARAM_COUNT)
        .create(create)
        .destroy(destroy)
        .declare(declare)
        .run_pass(run_pass)
        .report_json(report_json);

}  // namespace pfx_bloom
