// The "dof" effect on the GPU: the declared passes of each mode.
//
// seed    lens   depth -> lens (1x1: C, 1/P; autofocus reads the depth here)
//         half   color -> half (half-size copy, safe colour)
//         seed   color, depth, half, lens -> output (16 taps, mixed in as |CoC| passes 1 px)
#include "dof_effect.hpp"

#include <cmath>
#include <cstdio>
#include <new>
#include <string>

#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/gl_program.hpp>

#include "dof_camera.hpp"
#include "dof_params.hpp"
#include "dof_shaders.hpp"
#include "reference/dof_seed_model.hpp"

namespace pfx_dof {
namespace {

enum PassTag : uint32_t { PASS_LENS, PASS_SEED_HALF, PASS_SEED };
enum Program { PROGRAM_LENS, PROGRAM_SEED_HALF, PROGRAM_SEED, PROGRAM_COUNT };

constexpr uint32_t kMaxTargets = 8, kMaxPasses = 8;

struct Instance {
  const pfx_host* host = nullptr;
  GLuint programs[PROGRAM_COUNT] = {};
  // What declare hands the host; valid until the next declare or destroy, as the ABI asks.
  pfx_target_desc targets[kMaxTargets] = {};
  pfx_pass_desc passes[kMaxPasses] = {};
  pfx_pass_input lens_inputs[1] = {};
  pfx_pass_input half_inputs[1] = {};
  pfx_pass_input seed_inputs[4] = {};
  char report[256] = "";
  std::string last_problem;
};

void log(const Instance* inst, pfx_log_level level, const std::string& message) {
  inst->host->log(inst->host->host_data, level, ("dof: " + message).c_str());
}

void destroy(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst) return;
  for (GLuint program : inst->programs) glDeleteProgram(program);  // 0 is a silent no-op
  delete inst;
}

GLuint build(Instance* inst, const char* name, const std::string& body) {
  std::string error;
  const std::string source = std::string(shaders::kCommon) + body;
  GLuint program = pfx::gl::build_fullscreen_program(source.c_str(), &error);
  if (!program) log(inst, PFX_LOG_ERROR, std::string("shader '") + name + "': " + error);
  return program;
}

pfx_status create(const pfx_host* host, void** out) {
  if (!host || !out || host->struct_size < sizeof(pfx_host)) return PFX_INVALID_ARGUMENT;
  if (!pfx::gl::load_gl(host)) {
    host->log(host->host_data, PFX_LOG_ERROR, "dof: the host's context lacks OpenGL 4.5 core");
    return PFX_GL_ERROR;
  }
  Instance* inst = new (std::nothrow) Instance;
  if (!inst) return PFX_OUT_OF_MEMORY;
  inst->host = host;
  try {
    const char* names[PROGRAM_COUNT] = {"lens", "seed_half", "seed"};
    const std::string bodies[PROGRAM_COUNT] = {shaders::kLens, shaders::kSeedHalf, shaders::seed_body()};
    for (int i = 0; i < PROGRAM_COUNT; ++i) {
      inst->programs[i] = build(inst, names[i], bodies[i]);
      if (!inst->programs[i]) {
        destroy(inst);
        return PFX_GL_ERROR;
      }
    }
  } catch (...) {  // std::bad_alloc from a string; nothing may cross the ABI
    destroy(inst);
    return PFX_OUT_OF_MEMORY;
  }
  const pfx_pass_input depth = {PFX_INPUT_NAME_DEPTH, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  const pfx_pass_input color = {PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  inst->lens_inputs[0] = depth;
  inst->half_inputs[0] = color;
  inst->seed_inputs[0] = color;
  inst->seed_inputs[1] = depth;
  inst->seed_inputs[2] = {"half", PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  inst->seed_inputs[3] = {"lens", PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  *out = inst;
  return PFX_OK;
}

pfx_target_desc fixed_target(const char* name, pfx_format format, uint32_t width, uint32_t height) {
  pfx_target_desc t{};
  t.struct_size = sizeof t;
  t.name = name;
  t.format = format;
  t.size_mode = PFX_SIZE_FIXED;
  t.width = width;
  t.height = height;
  return t;
}

pfx_status declare(void* self, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !frame || !params || !out || frame->struct_size < sizeof(pfx_frame) ||
      out->struct_size < sizeof(pfx_declaration))
    return PFX_INVALID_ARGUMENT;
  const std::string problem = camera_problem(*frame);
  if (!problem.empty()) {
    // declare runs every frame: say it once, not sixty times a second.
    if (problem != inst->last_problem) log(inst, PFX_LOG_ERROR, problem);
    inst->last_problem = problem;
    return PFX_INVALID_ARGUMENT;
  }
  inst->last_problem.clear();
  const Settings s = settings_from(params);
  const uint32_t hw = static_cast<uint32_t>(half_size(static_cast<int>(frame->width)));
  const uint32_t hh = static_cast<uint32_t>(half_size(static_cast<int>(frame->height)));
  uint32_t t = 0, n = 0;
  inst->targets[t++] = fixed_target("lens", PFX_FORMAT_RG32F, 1, 1);
  inst->passes[n++] = pfx::desc::fullscreen_pass("lens", "lens", inst->lens_inputs, 1, PFX_BLEND_NONE,
                                                 PFX_LOAD_DONT_CARE, PASS_LENS);
  (void)s;
  inst->targets[t++] = fixed_target("half", PFX_FORMAT_RGBA16F, hw, hh);
  inst->passes[n++] = pfx::desc::fullscreen_pass("half", "half", inst->half_inputs, 1, PFX_BLEND_NONE,
                                                 PFX_LOAD_DONT_CARE, PASS_SEED_HALF);
  inst->passes[n++] = pfx::desc::fullscreen_pass("seed", PFX_OUTPUT_NAME, inst->seed_inputs, 4, PFX_BLEND_NONE,
                                                 PFX_LOAD_DONT_CARE, PASS_SEED);
  out->targets = inst->targets;
  out->target_count = t;
  out->passes = inst->passes;
  out->pass_count = n;
  return PFX_OK;
}

void set_common_uniforms(GLuint program, const pfx_frame& frame, const Settings& s) {
  glProgramUniform1i(program, 0, static_cast<GLint>(frame.depth_encoding));
  glProgramUniform2f(program, 1, frame.camera.near_plane, std::isinf(frame.camera.far_plane) ? 0.0f : frame.camera.far_plane);
  glProgramUniform1i(program, 2, std::isinf(frame.camera.far_plane) ? 1 : 0);
  glProgramUniform1f(program, 3, static_cast<float>(s.max_coc));
}

pfx_status run_pass(void* self, const pfx_pass_context* context) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !context || context->struct_size < sizeof(pfx_pass_context)) return PFX_INVALID_ARGUMENT;
  const pfx_frame& frame = *context->frame;
  const Settings s = settings_from(context->params);
  GLuint program = 0;
  switch (context->user_tag) {
    case PASS_LENS: {
      program = inst->programs[PROGRAM_LENS];
      const Lens lens = make_lens(frame, s, s.focus_distance);
      uint32_t fx = 0, fy = 0;
      focus_texel(frame.width, frame.height, s, &fx, &fy);
      glProgramUniform4f(program, 4, static_cast<float>(lens.image_distance_mm), static_cast<float>(lens.px_per_mm),
                         static_cast<float>(s.f_number), static_cast<float>(lens.focus_distance_m));
      glProgramUniform2i(program, 5, static_cast<GLint>(fx), static_cast<GLint>(fy));
      glProgramUniform1i(program, 6, s.autofocus == AUTOFOCUS_POINT ? 1 : 0);
      glProgramUniform2f(program, 7, static_cast<float>(kMinFocusDistance), static_cast<float>(kMaxFocusDistance));
      break;
    }
    case PASS_SEED_HALF:
      program = inst->programs[PROGRAM_SEED_HALF];
      glProgramUniform2f(program, 4, static_cast<float>(context->output_width), static_cast<float>(context->output_height));
      break;
    case PASS_SEED: program = inst->programs[PROGRAM_SEED]; break;
    default: return PFX_INVALID_ARGUMENT;
  }
  set_common_uniforms(program, frame, s);
  glUseProgram(program);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(0);
  return PFX_OK;
}

const char* report_json(void* self) {
  Instance* inst = static_cast<Instance*>(self);
  std::snprintf(inst->report, sizeof inst->report, "\"mode\": \"seed\"");
  return inst->report;
}

}  // namespace

const pfx_effect_desc kDofEffect = {
    sizeof(pfx_effect_desc),
    "dof",
    "Depth of field",
    "Thin-lens depth of field from the frame's depth and camera: the seed's 16-tap disk, or a halo-free "
    "near/far gather over 16 px CoC tiles.",
    kParams,
    PARAM_COUNT,
    create,
    destroy,
    declare,
    run_pass,
    report_json};

}  // namespace pfx_dof
