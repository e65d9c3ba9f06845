#pragma once
// Whether a pass's vertex shader puts its triangle where ReShade.fxh's PostProcessVS does, over
// the whole target: PostProcessVS itself, or a wrapper that hands its SV_VertexID and SV_Position
// straight to PostProcessVS and computes only further outputs of its own (SMAA's three wrappers
// add the offsets each of its passes samples at). A pass drawn so writes every pixel it does not
// discard, so it need not start from a copy of the picture.
#include "../ast/ast.hpp"
#include "effect_model.hpp"

namespace pfx::fx {

// A wrapper counts when its body (no return statement) calls PostProcessVS(ID, POSITION, ...) as a
// statement of its own at the top level, with ID its SV_VertexID input and POSITION its
// SV_Position output, and names neither anywhere else: nothing else can move the position or
// change the vertex number first.
bool draws_full_screen_triangle(const FunctionDecl* vertex_shader);

// Whether a pass that writes the back buffer writes every pixel of it, so it need not start from
// a copy of the picture: the standard full-screen triangle, no blending, every channel, no
// discard (`may_discard`: the generated pixel shader's), no stencil test.
bool covers_back_buffer(const PassInfo& pass, bool may_discard);

}  // namespace pfx::fx
