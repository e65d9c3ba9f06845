// The pyramid modes as declared passes (chain: the half-size pyramid of Call of Duty: Advanced
// Warfare; chain13: Jimenez's 13-tap downsample).
//
//   bright      color   -> level0            (5 taps, or 13 with a Karis average, x strength/levels;
//                                              chain with karis: the 5 taps Karis-weighted)
//   down i      level i-1 -> level i          (16 or 13 bilinear taps, clamp-to-border)   i = 1..L-1
//   up i        level i+1 -> level i, added   (3x3 tent from 4 taps, clamp-to-edge)       i = L-2..0
//   composite   color + tent(level0) -> output
#include "bloom_passes.hpp"

namespace pfx_bloom {
namespace {

const IndexedNames kLevelNames("level"), kDownNames("down"), kUpNames("up");

}  // namespace

void declare_chain(const Settings&, const LevelPlan& plan, DeclarationBuilder& out) {
  const int levels = plan.count;
  for (int i = 0; i < levels; ++i) out.target(kLevelNames[i], plan.width[i], plan.height[i]);
  // The frame is read texel by texel (the bright pass filters in arithmetic), the levels with the
  // pyramid's usual wrap modes: black border going down, edge going up.
  out.pass("bright", kLevelNames[0]).input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST).tag(pass_tag(PASS_BRIGHT, 0));
  for (int i = 1; i < levels; ++i)
    out.pass(kDownNames[i], kLevelNames[i])
        .input(kLevelNames[i - 1], PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_BORDER)
        .tag(pass_tag(PASS_DOWN, i));
  for (int i = levels - 2; i >= 0; --i)
    out.pass(kUpNames[i], kLevelNames[i])
        .input(kLevelNames[i + 1])
        .blend(PFX_BLEND_ADD)
        .load(PFX_LOAD_KEEP)
        .tag(pass_tag(PASS_UP, i));
  out.pass("composite", PFX_OUTPUT_NAME)
      .input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST)
      .input(kLevelNames[0])
      .tag(pass_tag(PASS_COMPOSITE, 0));
}

void run_chain_pass(const GLuint* programs, const Settings& s, const LevelPlan& plan, const pfx_pass_context& context) {
  const bool thirteen = s.mode == MODE_CHAIN13;
  GLuint program = 0;
  switch (tag_kind(context.user_tag)) {
    case PASS_BRIGHT: {
      program = programs[thirteen ? PROGRAM_BRIGHT13 : PROGRAM_BRIGHT];
      set_bright_uniforms(program, s);
      // Every level gets strength / levels, as in the pyramid: each adds the same light going up.
      const double per_level = s.strength / plan.count;
      glProgramUniform3f(program, 4, static_cast<float>(per_level * s.tint[0]), static_cast<float>(per_level * s.tint[1]),
                         static_cast<float>(per_level * s.tint[2]));
      glProgramUniform1f(program, 5, static_cast<float>(kLevelSumMax / plan.count));
      if (!thirteen) glProgramUniform1i(program, 6, s.karis ? 1 : 0);
      break;
    }
    case PASS_DOWN: program = programs[thirteen ? PROGRAM_DOWN13 : PROGRAM_DOWN]; break;
    case PASS_UP: program = programs[PROGRAM_UP]; break;
    case PASS_COMPOSITE:
      program = programs[PROGRAM_COMPOSITE];
      set_nonfinite_uniform(program, s);
      break;
    default: return;
  }
  glProgramUniform2f(program, 0, static_cast<float>(context.output_width), static_cast<float>(context.output_height));
  draw_fullscreen(program);
}

}  // namespace pfx_bloom
