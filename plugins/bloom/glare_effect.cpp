// The "glare" effect on the GPU: Kawase's star streaks as declared passes.
//
//   bright        color -> bright            (block average of the bloom's bright part: blocks of 1, 2 or
//                                              4 pixels covering the frame, rounded up, bloom_levels.hpp)
//   streak j.i    bright or streak_tmp -> ... (16 taps b*s texels along direction j, b = 4^i, i = 0..2;
//                                              pass 2 adds into streaks)          j = 0..streaks-1
//   composite     color + strength * tint * bilinear(streaks) -> output
//
// Each pass's weights a^(b*s) are normalised to sum to 1 and the last pass's divided by the streak
// count, so strength 1 spreads exactly the light above the threshold over all streaks (Kawase's
// leaves them unnormalised: at a = 0.925 each of its streaks carries 9.5 * 3.7 * 1.4 = 49 times the light).
#include "glare_effect.hpp"

#include <cstdio>
#include <new>
#include <string>

#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include "bloom_gl.hpp"
#include "bloom_levels.hpp"
#include "bloom_shaders.hpp"
#include "declaration_builder.hpp"
#include "glare_params.hpp"

namespace pfx_bloom {
namespace {

enum GlareProgram { GLARE_PROGRAM_BRIGHT, GLARE_PROGRAM_STREAK, GLARE_PROGRAM_COMPOSITE, GLARE_PROGRAM_COUNT };
enum GlarePassKind : uint32_t { GLARE_PASS_BRIGHT, GLARE_PASS_STREAK, GLARE_PASS_COMPOSITE };

constexpr uint32_t glare_tag(GlarePassKind kind, int streak, int pass) {
  return static_cast<uint32_t>(kind) << 8 | static_cast<uint32_t>(streak * kGlarePasses + pass);
}

const IndexedNames kStreakPassNames("streak");  // "streak<j*3+i>"
const char* const kTempNames[2] = {"streak_tmp0", "streak_tmp1"};

const ProgramSpec kPrograms[GLARE_PROGRAM_COUNT] = {
    {"glare_bright", shaders::box_bright}, {"streak", shaders::streak}, {"glare_composite", shaders::glare_composite}};

struct Instance {
  GLuint programs[GLARE_PROGRAM_COUNT] = {};
  DeclarationBuilder declaration;
  char report[96] = "";
  int last_streaks = 0, last_downscale = 0;
};

void destroy(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst) return;
  for (GLuint program : inst->programs) glDeleteProgram(program);
  delete inst;
}

pfx_status create(const pfx_host* host, void** out) {
  if (!pfx::plugin::usable_host(host) || !out) return PFX_INVALID_ARGUMENT;
  if (!load_gl(host)) return PFX_GL_ERROR;
  Instance* inst = new (std::nothrow) Instance;
  if (!inst) return PFX_OUT_OF_MEMORY;
  if (!build_programs(host, kPrograms, GLARE_PROGRAM_COUNT, inst->programs)) {
    destroy(inst);
    return PFX_GL_ERROR;
  }
  *out = inst;
  return PFX_OK;
}

int buffer_side(uint32_t frame_side, int downscale) { return blocks_covering(static_cast<int>(frame_side), downscale); }
int padding(uint32_t frame_side, int downscale) { return padding_before(static_cast<int>(frame_side), downscale); }

pfx_status declare(void* self, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !pfx::plugin::usable_declare_arguments(frame, params, out)) return PFX_INVALID_ARGUMENT;
  const GlareSettings g = glare_settings_from(params);
  DeclarationBuilder& d = inst->declaration;
  d.clear();
  inst->last_streaks = inst->last_downscale = 0;
  if (g.is_noop()) return PFX_OK;
  inst->last_streaks = g.streaks;
  inst->last_downscale = g.downscale;
  const int w = buffer_side(frame->width, g.downscale), h = buffer_side(frame->height, g.downscale);
  d.target("bright", w, h);
  d.target(kTempNames[0], w, h);
  d.target(kTempNames[1], w, h);
  d.target("streaks", w, h);
  d.pass("bright", "bright").input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST).tag(glare_tag(GLARE_PASS_BRIGHT, 0, 0));
  for (int j = 0; j < g.streaks; ++j)
    for (int i = 0; i < kGlarePasses; ++i) {
      const char* source = i == 0 ? "bright" : kTempNames[i - 1];
      const bool last = i == kGlarePasses - 1;
      // The first streak clears the sum, every streak adds into it.
      d.pass(kStreakPassNames[j * kGlarePasses + i], last ? "streaks" : kTempNames[i])
          .input(source, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_BORDER)
          .blend(last ? PFX_BLEND_ADD : PFX_BLEND_NONE)
          .load(last ? (j == 0 ? PFX_LOAD_CLEAR : PFX_LOAD_KEEP) : PFX_LOAD_DONT_CARE)
          .tag(glare_tag(GLARE_PASS_STREAK, j, i));
    }
  d.pass("composite", PFX_OUTPUT_NAME)
      .input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST)
      .input("streaks")
      .tag(glare_tag(GLARE_PASS_COMPOSITE, 0, 0));
  // Every pass samples its inputs and draws its output.
  d.samples_and_draws();
  return d.finish(out);
}

pfx_status run_pass(void* self, const pfx_pass_context* context) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !context || context->struct_size < PFX_PASS_CONTEXT_MIN_SIZE) return PFX_INVALID_ARGUMENT;
  const GlareSettings g = glare_settings_from(context->params);
  const float out_w = static_cast<float>(context->output_width), out_h = static_cast<float>(context->output_height);
  const int index = static_cast<int>(context->user_tag & 0xffu);
  GLuint program = 0;
  switch (context->user_tag >> 8) {
    case GLARE_PASS_BRIGHT:
      program = inst->programs[GLARE_PROGRAM_BRIGHT];
      set_bright_uniforms(program, g.bright);
      glProgramUniform1i(program, 4, g.downscale);
      glProgramUniform3f(program, 5, 1.0f, 1.0f, 1.0f);
      glProgramUniform1f(program, 6, static_cast<float>(kLevelSumMax));
      glProgramUniform2i(program, 7, padding(context->frame->width, g.downscale), padding(context->frame->height, g.downscale));
      glProgramUniform1i(program, 8, 0);  // plain block averages
      break;
    case GLARE_PASS_STREAK: {
      program = inst->programs[GLARE_PROGRAM_STREAK];
      const int streak = index / kGlarePasses, pass = index % kGlarePasses;
      double dx, dy, weights[kGlareTaps];
      g.direction(streak, &dx, &dy);
      g.pass_weights(pass, weights);
      const double b = pass == 0 ? 1.0 : pass == 1 ? 4.0 : 16.0;
      const double share = pass == kGlarePasses - 1 ? 1.0 / g.streaks : 1.0;
      float as_float[kGlareTaps];
      for (int s = 0; s < kGlareTaps; ++s) as_float[s] = static_cast<float>(weights[s] * share);
      glProgramUniform2f(program, 4, static_cast<float>(dx * b / out_w), static_cast<float>(dy * b / out_h));
      glProgramUniform1fv(program, 5, kGlareTaps, as_float);
      break;
    }
    case GLARE_PASS_COMPOSITE:
      program = inst->programs[GLARE_PROGRAM_COMPOSITE];
      set_nonfinite_uniform(program, g.bright);
      glProgramUniform3f(program, 4, static_cast<float>(g.strength * g.tint[0]), static_cast<float>(g.strength * g.tint[1]),
                         static_cast<float>(g.strength * g.tint[2]));
      glProgramUniform1f(program, 5, static_cast<float>(g.downscale));
      glProgramUniform2f(program, 6, static_cast<float>(padding(context->frame->width, g.downscale)),
                         static_cast<float>(padding(context->frame->height, g.downscale)));
      break;
    default: return PFX_INVALID_ARGUMENT;
  }
  glProgramUniform2f(program, 0, out_w, out_h);
  draw_fullscreen(program);
  return PFX_OK;
}

const char* report_json(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  std::snprintf(inst->report, sizeof inst->report, "\"streaks\": %d, \"downscale\": %d", inst->last_streaks,
                inst->last_downscale);
  return inst->report;
}

}  // namespace

const pfx_effect_desc kGlareEffect =
    pfx::desc::effect("glare")
        .label("Glare")
        .description(
            "Star streaks from bright light (Kawase's cross filter): 4, 6 or 8 streaks, each three passes of "
            "16 taps, added to the frame.")
        .params(kGlareParams, GLARE_PARAM_COUNT)
        .create(create)
        .destroy(destroy)
        .declare(declare)
        .run_pass(run_pass)
        .report_json(report_json);

}  // namespace pfx_bloom
