// The Gaussian modes as declared passes.
//
// gaussian (one separable Gaussian), one buffer of ceil(frame / downscale) blocks (bloom_levels.hpp):
//   bright      color -> blur0              (block average of each pixel's max(c - threshold, 0))
//   blur_y0     blur0 -> blur_tmp0          (vertical Gaussian first)
//   blur_x0     blur_tmp0 -> blur0_out      (horizontal)
//   composite   color * tone_scale + bilinear(blur0_out) -> output
//
// mgf (Kawase's multi-Gaussian), buffers of blocks of 4, 8 ... pixels; each Gaussian has deviation 2.5 texels of
// its buffer and the next buffer is made from the previous blurred one, as Kawase does:
//   bright      color -> blur0              (block average of 4x4 bright parts; with karis Karis-weighted)
//   blur_x i    blur i (i = 0) or gauss i-1 (each tap the 2x2 texels it covers) -> blur_tmp i
//   blur_y i    blur_tmp i -> gauss i
//   composite   color + sum of w_i * bilinear(gauss i) -> output
#include "bloom_passes.hpp"

#include "gaussian_taps.hpp"

namespace pfx_bloom {
namespace {

const IndexedNames kBlurNames("blur"), kTempNames("blur_tmp"), kGaussNames("gauss");
const IndexedNames kBlurXNames("blur_x"), kBlurYNames("blur_y");

pfx_pass_input linear_border(const char* name) { return input(name, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_BORDER); }
pfx_pass_input linear_edge(const char* name) { return input(name, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE); }
pfx_pass_input frame_texels() { return input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE); }

void declare_bright(DeclarationBuilder& out, const LevelPlan& plan) {
  out.target(kBlurNames[0], plan.width[0], plan.height[0]);
  out.pass("bright", kBlurNames[0]).input(frame_texels()).tag(pass_tag(PASS_BOX_BRIGHT, 0));
}

void set_blur_uniforms(GLuint program, double deviation, int half_taps, bool horizontal, bool finer_source) {
  double weights[kMaxHalfTaps + 1];
  gaussian_weights(deviation, half_taps, weights);
  float as_float[kMaxHalfTaps + 1];
  for (int k = 0; k <= half_taps; ++k) as_float[k] = static_cast<float>(weights[k]);
  glProgramUniform2i(program, 4, horizontal ? 1 : 0, horizontal ? 0 : 1);
  glProgramUniform1i(program, 5, half_taps);
  glProgramUniform1fv(program, 6, half_taps + 1, as_float);
  glProgramUniform1i(program, 520, finer_source ? 1 : 0);
}

}  // namespace

void declare_gaussian(const Settings& s, const LevelPlan& plan, DeclarationBuilder& out) {
  if (!s.adds_nothing()) {
    declare_bright(out, plan);
    out.target(kTempNames[0], plan.width[0], plan.height[0]);
    out.target(kGaussNames[0], plan.width[0], plan.height[0]);
    out.pass(kBlurYNames[0], kTempNames[0]).input(linear_border(kBlurNames[0])).tag(pass_tag(PASS_BLUR_Y, 0));
    out.pass(kBlurXNames[0], kGaussNames[0]).input(linear_border(kTempNames[0])).tag(pass_tag(PASS_BLUR_X, 0));
    out.pass("composite", PFX_OUTPUT_NAME)
        .input(frame_texels())
        .input(linear_edge(kGaussNames[0]))
        .tag(pass_tag(PASS_GAUSSIAN_COMPOSITE, 0));
  } else {  // only the tone scale changes the frame
    out.pass("composite", PFX_OUTPUT_NAME).input(frame_texels()).tag(pass_tag(PASS_GAUSSIAN_COMPOSITE, 0));
  }
}

void declare_mgf(const Settings&, const LevelPlan& plan, DeclarationBuilder& out) {
  declare_bright(out, plan);
  for (int i = 0; i < plan.count; ++i) {
    out.target(kTempNames[i], plan.width[i], plan.height[i]);
    out.target(kGaussNames[i], plan.width[i], plan.height[i]);
    const char* source = i == 0 ? kBlurNames[0] : kGaussNames[i - 1];
    out.pass(kBlurXNames[i], kTempNames[i]).input(linear_border(source)).tag(pass_tag(PASS_BLUR_X, i));
    out.pass(kBlurYNames[i], kGaussNames[i]).input(linear_border(kTempNames[i])).tag(pass_tag(PASS_BLUR_Y, i));
  }
  auto composite = out.pass("composite", PFX_OUTPUT_NAME).input(frame_texels()).tag(pass_tag(PASS_MGF_COMPOSITE, 0));
  for (int i = 0; i < plan.count; ++i) composite.input(linear_edge(kGaussNames[i]));
}

void run_blur_pass(const GLuint* programs, const Settings& s, const LevelPlan& plan, const pfx_pass_context& context) {
  const float out_w = static_cast<float>(context.output_width), out_h = static_cast<float>(context.output_height);
  const bool mgf = s.mode == MODE_MGF;
  GLuint program = 0;
  switch (tag_kind(context.user_tag)) {
    case PASS_BOX_BRIGHT: {
      program = programs[PROGRAM_BOX_BRIGHT];
      // gaussian thresholds every channel on its own; Kawase leaves the mgf's bright pass open,
      // so it takes the bloom's own (the chain's, with its measure).
      set_bright_uniforms(program, s, mgf ? -1 : 2);
      glProgramUniform1i(program, 4, plan.block);
      glProgramUniform3f(program, 5, static_cast<float>(s.strength * s.tint[0]), static_cast<float>(s.strength * s.tint[1]),
                         static_cast<float>(s.strength * s.tint[2]));
      glProgramUniform1f(program, 6, static_cast<float>(kLevelSumMax));
      glProgramUniform2i(program, 7, plan.pad_x, plan.pad_y);
      glProgramUniform1i(program, 8, mgf && s.karis ? 1 : 0);
      break;
    }
    case PASS_BLUR_X:
    case PASS_BLUR_Y: {
      program = programs[PROGRAM_BLUR];
      const bool x = tag_kind(context.user_tag) == PASS_BLUR_X;
      const double deviation = mgf ? kMgfDeviation : gaussian_mode_deviation(s);
      const int half_taps = mgf ? kMgfTaps / 2 : s.half_taps;
      // mgf's buffer i > 0 is made by its first (horizontal) blur, from the finer buffer i - 1.
      const bool finer_source = mgf && x && tag_index(context.user_tag) > 0;
      set_blur_uniforms(program, deviation, half_taps, x, finer_source);
      break;
    }
    case PASS_GAUSSIAN_COMPOSITE:
      program = programs[PROGRAM_GAUSSIAN_COMPOSITE];
      set_nonfinite_uniform(program, s);
      glProgramUniform1f(program, 4, static_cast<float>(s.tone_scale));
      glProgramUniform1i(program, 5, context.input_count > 1 ? 1 : 0);
      glProgramUniform1f(program, 6, static_cast<float>(plan.block));
      glProgramUniform2f(program, 7, static_cast<float>(plan.pad_x), static_cast<float>(plan.pad_y));
      break;
    case PASS_MGF_COMPOSITE: {
      program = programs[PROGRAM_MGF_COMPOSITE];
      set_nonfinite_uniform(program, s);
      double weights[kMaxLevels];
      level_weights(s, plan.count, weights);
      float as_float[kMaxLevels];
      for (int i = 0; i < plan.count; ++i) as_float[i] = static_cast<float>(weights[i]);
      glProgramUniform1i(program, 4, plan.count);
      glProgramUniform1fv(program, 5, plan.count, as_float);
      glProgramUniform2f(program, 20, static_cast<float>(plan.pad_x), static_cast<float>(plan.pad_y));
      break;
    }
    default: return;
  }
  glProgramUniform2f(program, 0, out_w, out_h);
  draw_fullscreen(program);
}

}  // namespace pfx_bloom
