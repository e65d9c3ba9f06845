// The "bloom" effect on the GPU: the seed's chain as declared passes.
//
//   bright      color   -> level0            (5 bilinear taps of the bright part, x strength/levels)
//   down i      level i-1 -> level i          (16 bilinear taps, clamp-to-border)      i = 1..L-1
//   up i        level i+1 -> level i, added   (3x3 tent from 4 taps, clamp-to-edge)    i = L-2..0
//   composite   color + tent(level0) -> output
#include "bloom_effect.hpp"

#include <pfx/cpp/descriptors.hpp>

#include <cstdio>
#include <cstdlib>
#include <new>

#include "bloom_gl.hpp"
#include "bloom_levels.hpp"
#include "bloom_params.hpp"
#include "bloom_shaders.hpp"

namespace pfx_bloom {
namespace {

enum PassKind : uint32_t { PASS_BRIGHT, PASS_DOWN, PASS_UP, PASS_COMPOSITE };
enum Program { PROGRAM_BRIGHT, PROGRAM_DOWN, PROGRAM_UP, PROGRAM_COMPOSITE, PROGRAM_COUNT };

// user_tag = kind * 32 + level written: run_pass needs nothing else.
constexpr uint32_t tag(PassKind kind, int level) { return static_cast<uint32_t>(kind) * 32u + static_cast<uint32_t>(level); }

const char* const kLevelNames[kMaxLevels] = {"level0", "level1", "level2",  "level3",  "level4",  "level5",
                                             "level6", "level7", "level8",  "level9",  "level10", "level11",
                                             "level12", "level13", "level14", "level15"};
const char* const kDownNames[kMaxLevels] = {"", "down1", "down2", "down3", "down4", "down5", "down6", "down7",
                                            "down8", "down9", "down10", "down11", "down12", "down13", "down14",
                                            "down15"};
const char* const kUpNames[kMaxLevels] = {"up0", "up1", "up2", "up3", "up4", "up5", "up6", "up7",
                                          "up8", "up9", "up10", "up11", "up12", "up13", "up14", ""};

struct Instance {
  GLuint programs[PROGRAM_COUNT] = {};
  // What declare hands the host; valid until the next declare or destroy, as the ABI asks.
  pfx_target_desc targets[kMaxLevels] = {};
  pfx_pass_desc passes[2 * kMaxLevels] = {};
  pfx_pass_input bright_inputs[1] = {};
  pfx_pass_input down_inputs[kMaxLevels][1] = {};  // [i]: reads level i-1
  pfx_pass_input up_inputs[kMaxLevels][1] = {};    // [i]: reads level i+1
  pfx_pass_input composite_inputs[2] = {};
  char report[160] = "";
  LevelPlan last_plan;
};

void destroy(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst) return;
  for (GLuint program : inst->programs) glDeleteProgram(program);  // 0 is a silent no-op
  delete inst;
}

pfx_status create(const pfx_host* host, void** out) {
  if (!host || !out || host->struct_size < sizeof(pfx_host)) return PFX_INVALID_ARGUMENT;
  if (!load_gl(host)) return PFX_GL_ERROR;
  Instance* inst = new (std::nothrow) Instance;
  if (!inst) return PFX_OUT_OF_MEMORY;
  const char* names[PROGRAM_COUNT] = {"bright", "down", "up", "composite"};
  const char* sources[PROGRAM_COUNT] = {shaders::kBright, shaders::kDown, shaders::kUp, shaders::kComposite};
  for (int i = 0; i < PROGRAM_COUNT; ++i) {
    try {
      inst->programs[i] = build_program(host, names[i], sources[i]);
    } catch (...) {  // only std::bad_alloc from a log message; nothing may cross the ABI
      inst->programs[i] = 0;
    }
    if (!inst->programs[i]) {
      destroy(inst);
      return PFX_GL_ERROR;
    }
  }
  // The frame is sampled texel by texel (the bright pass filters in arithmetic), the levels with the
  // seed's wrap modes: black border going down, edge going up.
  inst->bright_inputs[0] = {PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  for (int i = 0; i < kMaxLevels; ++i) {
    if (i > 0) inst->down_inputs[i][0] = {kLevelNames[i - 1], PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_BORDER};
    if (i + 1 < kMaxLevels) inst->up_inputs[i][0] = {kLevelNames[i + 1], PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  }
  inst->composite_inputs[0] = {PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  inst->composite_inputs[1] = {kLevelNames[0], PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  *out = inst;
  return PFX_OK;
}

pfx_status declare(void* self, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !frame || !params || !out || frame->struct_size < sizeof(pfx_frame) ||
      out->struct_size < sizeof(pfx_declaration))
    return PFX_INVALID_ARGUMENT;
  const Settings settings = settings_from(params);
  if (settings.is_noop()) {
    inst->last_plan = LevelPlan{};
    return PFX_OK;  // no passes: the host skips the effect
  }
  const LevelPlan plan = plan_levels(frame->width, frame->height, settings.levels, settings.auto_min_size);
  inst->last_plan = plan;
  const int levels = plan.count;
  for (int i = 0; i < levels; ++i) {
    pfx_target_desc& t = inst->targets[i];
    t = pfx_target_desc{};
    t.struct_size = sizeof t;
    t.name = kLevelNames[i];
    t.format = PFX_FORMAT_RGBA16F;
    t.size_mode = PFX_SIZE_FIXED;
    t.width = static_cast<uint32_t>(plan.width[i]);
    t.height = static_cast<uint32_t>(plan.height[i]);
  }
  uint32_t n = 0;
  inst->passes[n++] = pfx::desc::fullscreen_pass("bright", kLevelNames[0], inst->bright_inputs, 1, PFX_BLEND_NONE,
                                PFX_LOAD_DONT_CARE, tag(PASS_BRIGHT, 0));
  for (int i = 1; i < levels; ++i)
    inst->passes[n++] = pfx::desc::fullscreen_pass(kDownNames[i], kLevelNames[i], inst->down_inputs[i], 1, PFX_BLEND_NONE,
                                  PFX_LOAD_DONT_CARE, tag(PASS_DOWN, i));
  for (int i = levels - 2; i >= 0; --i)
    inst->passes[n++] = pfx::desc::fullscreen_pass(kUpNames[i], kLevelNames[i], inst->up_inputs[i], 1, PFX_BLEND_ADD, PFX_LOAD_KEEP,
                                  tag(PASS_UP, i));
  inst->passes[n++] = pfx::desc::fullscreen_pass("composite", PFX_OUTPUT_NAME, inst->composite_inputs, 2, PFX_BLEND_NONE,
                                PFX_LOAD_DONT_CARE, tag(PASS_COMPOSITE, 0));
  out->targets = inst->targets;
  out->target_count = static_cast<uint32_t>(levels);
  out->passes = inst->passes;
  out->pass_count = n;
  return PFX_OK;
}

void draw(GLuint program) {
  glUseProgram(program);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(0);
}

pfx_status run_pass(void* self, const pfx_pass_context* context) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !context || context->struct_size < sizeof(pfx_pass_context)) return PFX_INVALID_ARGUMENT;
  const float out_w = static_cast<float>(context->output_width), out_h = static_cast<float>(context->output_height);
  const uint32_t kind = context->user_tag / 32u;
  GLuint program = 0;
  switch (kind) {
    case PASS_BRIGHT: {
      const Settings s = settings_from(context->params);
      const LevelPlan plan = plan_levels(context->frame->width, context->frame->height, s.levels, s.auto_min_size);
      const double per_level = s.strength / plan.count;
      program = inst->programs[PROGRAM_BRIGHT];
      glProgramUniform2f(program, 1, static_cast<float>(s.threshold), static_cast<float>(s.knee));
      glProgramUniform1i(program, 2, s.measure);
      glProgramUniform1f(program, 3, static_cast<float>(s.firefly_clamp));
      glProgramUniform3f(program, 4, static_cast<float>(per_level * s.tint[0]), static_cast<float>(per_level * s.tint[1]),
                         static_cast<float>(per_level * s.tint[2]));
      glProgramUniform1f(program, 5, static_cast<float>(kLevelSumMax / plan.count));
      break;
    }
    case PASS_DOWN: program = inst->programs[PROGRAM_DOWN]; break;
    case PASS_UP: program = inst->programs[PROGRAM_UP]; break;
    case PASS_COMPOSITE: program = inst->programs[PROGRAM_COMPOSITE]; break;
    default: return PFX_INVALID_ARGUMENT;
  }
  glProgramUniform2f(program, 0, out_w, out_h);
  draw(program);
  return PFX_OK;
}

const char* report_json(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  const LevelPlan& plan = inst->last_plan;
  const int last = plan.count > 0 ? plan.count - 1 : 0;
  std::snprintf(inst->report, sizeof inst->report, "\"levels\": %d, \"smallest_level\": \"%dx%d\"", plan.count,
                plan.width[last], plan.height[last]);
  return inst->report;
}

}  // namespace

const pfx_effect_desc kBloomEffect = {
    sizeof(pfx_effect_desc),
    "bloom",
    "Bloom",
    "Light above a threshold spreads into its surroundings through a half-size pyramid (the seed's chain).",
    kParams,
    PARAM_COUNT,
    create,
    destroy,
    declare,
    run_pass,
    report_json};

}  // namespace pfx_bloom
