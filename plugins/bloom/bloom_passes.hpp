// The "bloom" effect's passes, mode by mode: what declare asks of the host (declare_*), and what
// run_pass does for each declared pass (run_*). A pass's user_tag is pass_tag(kind, index).
#pragma once

#include <cstdint>

#include <glad/gl.h>
#include <pfx/effect.h>

#include "bloom_gl.hpp"
#include "bloom_levels.hpp"
#include "bloom_params.hpp"
#include "declaration_builder.hpp"

namespace pfx_bloom {

enum Program {
  PROGRAM_BRIGHT,
  PROGRAM_DOWN,
  PROGRAM_UP,
  PROGRAM_COMPOSITE,
  PROGRAM_BRIGHT13,
  PROGRAM_DOWN13,
  PROGRAM_BOX_BRIGHT,
  PROGRAM_BLUR,
  PROGRAM_GAUSSIAN_COMPOSITE,
  PROGRAM_MGF_COMPOSITE,
  PROGRAM_COUNT
};

enum PassKind : uint32_t {
  PASS_BRIGHT,       // chain, chain13: frame -> level 0
  PASS_DOWN,         // chain, chain13: level i-1 -> level i
  PASS_UP,           // chain, chain13: level i+1 -> added into level i
  PASS_COMPOSITE,    // chain, chain13: frame + level 0 -> output
  PASS_BOX_BRIGHT,   // gaussian, mgf: frame -> the first buffer
  PASS_BLUR_X,       // gaussian, mgf: horizontal Gaussian of buffer i
  PASS_BLUR_Y,       // gaussian, mgf: vertical Gaussian of buffer i
  PASS_GAUSSIAN_COMPOSITE,
  PASS_MGF_COMPOSITE
};

constexpr uint32_t pass_tag(PassKind kind, int index) { return static_cast<uint32_t>(kind) << 8 | static_cast<uint32_t>(index); }
constexpr PassKind tag_kind(uint32_t tag) { return static_cast<PassKind>(tag >> 8); }
constexpr int tag_index(uint32_t tag) { return static_cast<int>(tag & 0xffu); }

// Frame -> output through the plan's levels.
void declare_chain(const Settings& s, const LevelPlan& plan, DeclarationBuilder& out);
void declare_gaussian(const Settings& s, const LevelPlan& plan, DeclarationBuilder& out);
void declare_mgf(const Settings& s, const LevelPlan& plan, DeclarationBuilder& out);

// Binds nothing but the program and its uniforms, draws one triangle, unbinds the program.
void run_chain_pass(const GLuint* programs, const Settings& s, const LevelPlan& plan, const pfx_pass_context& context);
void run_blur_pass(const GLuint* programs, const Settings& s, const LevelPlan& plan, const pfx_pass_context& context);

}  // namespace pfx_bloom
