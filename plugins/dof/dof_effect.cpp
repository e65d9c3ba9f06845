// The "dof" effect on the GPU: the declared passes of each mode.
//
// both      lens      depth -> lens (1x1: C, 1/P; autofocus reads the depth here)
// seed      half      color -> half (half-size copy of the safe colour)
//           seed      color, depth, half, lens -> output (16 taps, mixed in as |CoC| passes 1 px)
// gather    prepare   color, depth, lens -> work (safe colour + signed CoC, half or full resolution)
//           tiles     work -> tiles (largest near CoC and largest |CoC| per 16 frame px)
//           dilate    tiles -> dilated (near CoC spread to the tiles it can reach)
//           gather    work, dilated, color -> output (full) or blur (half): near/far ring gather
//           composite color, depth, lens, work, blur, dilated -> output (half only)
#include "dof_effect.hpp"

#include <cmath>
#include <cstdio>
#include <new>
#include <string>
#include <vector>

#include <pfx/cpp/declaration.hpp>
#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/gl_program.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include "dof_camera.hpp"
#include "dof_gather_plan.hpp"
#include "dof_params.hpp"
#include "dof_rings.hpp"
#include "dof_shaders.hpp"
#include "reference/dof_seed_model.hpp"

namespace pfx_dof {
namespace {

enum Program {
  PROGRAM_LENS,
  PROGRAM_SEED_HALF,
  PROGRAM_SEED,
  PROGRAM_PREPARE,
  PROGRAM_TILES,
  PROGRAM_DILATE,
  PROGRAM_GATHER,
  PROGRAM_COMPOSITE,
  PROGRAM_COUNT
};

// What declare hands the host (the gather mode's five targets and five passes at most).
using Declaration = pfx::desc::DeclarationBuilder<8, 8>;

// The inputs of every pass, by program; each pass's tag is its program.
struct PassInputs {
  pfx_pass_input lens[1], seed_half[1], seed[4], prepare[3], tiles[1], dilate[1], gather[3], composite[6];
};

struct Instance {
  const pfx_host* host = nullptr;
  GLuint programs[PROGRAM_COUNT] = {};
  GLuint rings = 0;         // shader storage: the gather's ring samples
  int ring_count = 0;       // the sample count they were made for
  PassInputs inputs{};
  Declaration declaration;  // valid until the next declare or destroy, as the ABI asks
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
  if (inst->rings) glDeleteBuffers(1, &inst->rings);
  delete inst;
}

GLuint build(Instance* inst, const char* name, const std::string& body) {
  std::string error;
  const std::string source = std::string(shaders::kCommon) + body;
  GLuint program = pfx::gl::build_fullscreen_program(source.c_str(), &error);
  if (!program) log(inst, PFX_LOG_ERROR, std::string("shader '") + name + "': " + error);
  return program;
}

void set_inputs(PassInputs* in) {
  const pfx_pass_input color = {PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  const pfx_pass_input depth = {PFX_INPUT_NAME_DEPTH, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  const pfx_pass_input lens = {"lens", PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  const pfx_pass_input work = {"work", PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  const pfx_pass_input dilated = {"dilated", PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  in->lens[0] = depth;
  in->seed_half[0] = color;
  in->seed[0] = color;
  in->seed[1] = depth;
  in->seed[2] = {"half", PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};  // the 16-tap disk's bilinear taps
  in->seed[3] = lens;
  // Linear: at half resolution one bilinear tap averages a 2x2 block (texel fetches ignore it).
  in->prepare[0] = {PFX_INPUT_NAME_COLOR, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  in->prepare[1] = {PFX_INPUT_NAME_DEPTH, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  in->prepare[2] = lens;
  in->tiles[0] = work;
  in->dilate[0] = {"tiles", PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  in->gather[0] = work;
  in->gather[1] = dilated;
  in->gather[2] = color;
  in->composite[0] = color;
  in->composite[1] = depth;
  in->composite[2] = lens;
  // Linear for the composite's bilinear taps (its texel fetches ignore the filter).
  in->composite[3] = {"work", PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  in->composite[4] = {"blur", PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  in->composite[5] = dilated;
}

pfx_status create(const pfx_host* host, void** out) {
  if (!pfx::plugin::usable_host(host) || !out) return PFX_INVALID_ARGUMENT;
  if (!pfx::gl::load_gl_or_log(host, "dof")) return PFX_GL_ERROR;
  Instance* inst = new (std::nothrow) Instance;
  if (!inst) return PFX_OUT_OF_MEMORY;
  inst->host = host;
  const pfx_status built = pfx::plugin::without_exceptions([&] {  // std::bad_alloc from a string
    const char* names[PROGRAM_COUNT] = {"lens", "seed_half", "seed", "prepare", "tiles", "dilate", "gather", "composite"};
    const std::string bodies[PROGRAM_COUNT] = {shaders::kLens,    shaders::kSeedHalf, shaders::seed_body(),
                                               shaders::kPrepare, shaders::kTiles,    shaders::kDilate,
                                               shaders::kGather,  shaders::kComposite};
    for (int i = 0; i < PROGRAM_COUNT; ++i) {
      inst->programs[i] = build(inst, names[i], bodies[i]);
      if (!inst->programs[i]) return PFX_GL_ERROR;
    }
    return PFX_OK;
  });
  if (built != PFX_OK) {
    destroy(inst);
    return built;
  }
  glCreateBuffers(1, &inst->rings);
  // [0, 256): the ring samples of the current count; [256, 512): the disc offsets, fixed.
  std::vector<float> offsets;
  for (const DiscOffset& o : disc_offsets())
    offsets.insert(offsets.end(), {static_cast<float>(o.x), static_cast<float>(o.y), o.length, 0.0f});
  glNamedBufferStorage(inst->rings, sizeof(float) * 4 * (kMaxSamples + kDiscOffsetCount), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferSubData(inst->rings, sizeof(float) * 4 * kMaxSamples,
                       static_cast<GLsizeiptr>(offsets.size() * sizeof(float)), offsets.data());
  set_inputs(&inst->inputs);
  *out = inst;
  return PFX_OK;
}

pfx_status declare(void* self, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !pfx::plugin::usable_declare_arguments(frame, params, out)) return PFX_INVALID_ARGUMENT;
  const std::string problem = camera_problem(*frame);
  if (!problem.empty()) {
    // declare runs every frame: say it once, not sixty times a second.
    if (problem != inst->last_problem) log(inst, PFX_LOG_ERROR, problem);
    inst->last_problem = problem;
    return PFX_INVALID_ARGUMENT;
  }
  inst->last_problem.clear();
  const Settings s = settings_from(params);
  PassInputs& in = inst->inputs;
  Declaration& d = inst->declaration;
  d.clear();
  auto pass = [&](const char* name, const char* output, const pfx_pass_input* inputs, uint32_t count, Program tag) {
    d.pass(name, output).inputs(inputs, count).tag(tag);
  };
  d.target("lens", 1, 1, PFX_FORMAT_RG32F);
  pass("lens", "lens", in.lens, 1, PROGRAM_LENS);
  if (s.mode == MODE_SEED) {
    d.target("half", half_size(static_cast<int>(frame->width)), half_size(static_cast<int>(frame->height)));
    pass("half", "half", in.seed_half, 1, PROGRAM_SEED_HALF);
    pass("seed", PFX_OUTPUT_NAME, in.seed, 4, PROGRAM_SEED);
    std::snprintf(inst->report, sizeof inst->report, "\"mode\": \"seed\", \"taps\": 16");
  } else {
    const GatherPlan plan = plan_gather(frame->width, frame->height, s);
    d.target("work", plan.work_width, plan.work_height);
    d.target("tiles", plan.tiles_width, plan.tiles_height, PFX_FORMAT_RG16F);
    d.target("dilated", plan.tiles_width, plan.tiles_height, PFX_FORMAT_RG16F);
    pass("prepare", "work", in.prepare, 3, PROGRAM_PREPARE);
    pass("tiles", "tiles", in.tiles, 1, PROGRAM_TILES);
    pass("dilate", "dilated", in.dilate, 1, PROGRAM_DILATE);
    if (plan.half) {
      d.target("blur", plan.work_width, plan.work_height);
      pass("gather", "blur", in.gather, 3, PROGRAM_GATHER);
      pass("composite", PFX_OUTPUT_NAME, in.composite, 6, PROGRAM_COMPOSITE);
    } else {
      pass("gather", PFX_OUTPUT_NAME, in.gather, 3, PROGRAM_GATHER);
    }
    std::snprintf(inst->report, sizeof inst->report,
                  "\"mode\": \"gather\", \"samples\": %d, \"work\": \"%dx%d\", \"tiles\": \"%dx%d\", \"dilation\": %d",
                  s.samples, plan.work_width, plan.work_height, plan.tiles_width, plan.tiles_height, plan.dilation);
  }
  // Every pass samples its inputs and draws its output.
  d.samples_and_draws();
  return d.finish(out);
}

void set_common_uniforms(GLuint program, const pfx_frame& frame, const Settings& s) {
  const bool infinite = std::isinf(frame.camera.far_plane);
  glProgramUniform1i(program, 0, static_cast<GLint>(frame.depth_encoding));
  glProgramUniform2f(program, 1, frame.camera.near_plane, infinite ? 0.0f : frame.camera.far_plane);
  glProgramUniform1i(program, 2, infinite ? 1 : 0);
  glProgramUniform1f(program, 3, static_cast<float>(s.max_coc));
  glProgramUniform1i(program, 30, s.nonfinite);
}

void set_lens_uniforms(GLuint program, const pfx_frame& frame, const Settings& s) {
  const Lens lens = make_lens(frame, s, s.focus_distance);
  uint32_t fx = 0, fy = 0;
  focus_texel(frame.width, frame.height, s, &fx, &fy);
  glProgramUniform4f(program, 4, static_cast<float>(lens.image_distance_mm), static_cast<float>(lens.px_per_mm),
                     static_cast<float>(s.f_number), static_cast<float>(lens.focus_distance_m));
  glProgramUniform2i(program, 5, static_cast<GLint>(fx), static_cast<GLint>(fy));
  glProgramUniform1i(program, 6, s.autofocus == AUTOFOCUS_POINT ? 1 : 0);
  glProgramUniform2f(program, 7, static_cast<float>(kMinFocusDistance), static_cast<float>(kMaxFocusDistance));
}

void upload_rings(Instance* inst, int count) {
  if (inst->ring_count == count) return;
  const std::vector<RingSample> rings = ring_samples(count);
  std::vector<float> data;
  for (const RingSample& r : rings) data.insert(data.end(), {r.x, r.y, r.area, 0.0f});
  glNamedBufferSubData(inst->rings, 0, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data());
  inst->ring_count = count;
}

pfx_status run_pass(void* self, const pfx_pass_context* context) {
  Instance* inst = static_cast<Instance*>(self);
  if (!inst || !context || context->struct_size < PFX_PASS_CONTEXT_MIN_SIZE || context->user_tag >= PROGRAM_COUNT)
    return PFX_INVALID_ARGUMENT;
  const pfx_frame& frame = *context->frame;
  const Settings s = settings_from(context->params);
  const GatherPlan plan = plan_gather(frame.width, frame.height, s);
  const GLuint program = inst->programs[context->user_tag];
  switch (context->user_tag) {
    case PROGRAM_LENS: set_lens_uniforms(program, frame, s); break;
    case PROGRAM_SEED_HALF:
      glProgramUniform2f(program, 4, static_cast<float>(context->output_width), static_cast<float>(context->output_height));
      break;
    case PROGRAM_PREPARE: glProgramUniform1i(program, 4, plan.half ? 1 : 0); break;
    case PROGRAM_TILES: glProgramUniform1i(program, 4, plan.tile); break;
    case PROGRAM_DILATE: glProgramUniform1i(program, 5, plan.dilation); break;
    case PROGRAM_GATHER:
      upload_rings(inst, s.samples);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, inst->rings);
      glProgramUniform1i(program, 4, inst->ring_count);
      glProgramUniform1f(program, 5, plan.half ? 0.5f : 1.0f);
      glProgramUniform1i(program, 6, plan.tile);
      glProgramUniform1i(program, 7, plan.half ? 0 : 1);
      break;
    default: break;
  }
  set_common_uniforms(program, frame, s);
  glUseProgram(program);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(0);
  return PFX_OK;
}

const char* report_json(void* self) { return static_cast<Instance*>(self)->report; }

}  // namespace

const pfx_effect_desc kDofEffect =
    pfx::desc::effect("dof")
        .label("Depth of field")
        .description("Thin-lens depth of field from the frame's depth and camera: a 16-tap disk gather from a "
                     "half-size copy, or a halo-free near/far gather over 16 px CoC tiles that leaves in-focus "
                     "tiles untouched.")
        .params(kParams)
        .create(create)
        .destroy(destroy)
        .declare(declare)
        .run_pass(run_pass)
        .report_json(report_json);

}  // namespace pfx_dof
