#pragma once
// Whether a pass's vertex shader puts its triangle where ReShade.fxh's PostProcessVS does, over
// the whole target: PostProcessVS itself, or a wrapper that hands its SV_VertexID and SV_Position
// straight to PostProcessVS and computes only further outputs of its own (SMAA's three wrappers
// add the offsets each of its passes samples at). A pass drawn so writes every pixel it does not
// discard, so it need not start from a copy of the picture.
#include "ast/ast.hpp"

namespace pfx_fx {

// A wrapper counts when its body (no return statement) calls PostProcessVS(ID, POSITION, ...) as a
// statement of its own at the top level, with ID its SV_VertexID input and POSITION its
// SV_Position output, and names neither anywhere else: nothing else can move the position or
// change the vertex number first.
bool draws_full_screen_triangle(const pfx::fx::FunctionDecl* vertex_shader);

}  // namespace pfx_fx
