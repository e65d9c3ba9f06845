// GLSL of the "dof" passes. Every program is kCommon followed by its body; uniform locations are
// listed with each and are what dof_effect.cpp sets.
#pragma once

#include <string>

namespace pfx_dof::shaders {

// Shared by every program: the depth decoding of pfx/depth.h (locations 0: int encoding,
// 1: vec2 near/far planes, 2: int far plane infinite), making colour safe, and the CoC from the
// lens texel (C, 1/P) with 3: float max CoC.
extern const char* const kCommon;

// depth -> lens (1x1 RG32F: C, 1/P). 4: vec4 (image distance mm, px per mm, f-number, focus
// distance m), 5: ivec2 autofocus texel, 6: int autofocus on, 7: vec2 focus distance hard range.
extern const char* const kLens;

// color -> half-size copy, one bilinear tap of the safe colour per half texel.
extern const char* const kSeedHalf;

// color, depth, half, lens -> output: the 16-tap disk. The disk is spliced in as text.
std::string seed_body();

// gather mode. prepare: color, depth, lens -> work (safe colour, a = signed CoC in frame pixels);
// 4: int half (2x2 blocks: mean colour, the nearest CoC).
extern const char* const kPrepare;
// work -> tiles (r: largest near CoC, g: largest |CoC|). 4: int work pixels per tile.
extern const char* const kTiles;
// tiles -> dilated (r: largest near CoC within 5: int tiles each way, g: the tile's own |CoC|).
extern const char* const kDilate;
// work, dilated, color -> output (full) or blur (half; a = what the near field leaves visible).
// The samples in the shader storage buffer at binding 0 (vec4s: 256 ring samples x, y, area, then
// dof_rings' 256 disc offsets x, y, length). 4: int sample
// count, 5: float work pixels per frame pixel, 6: int work pixels per tile, 7: int full resolution.
extern const char* const kGather;
// color, depth, lens, work, blur, dilated -> output: the half-resolution gather over the sharp frame.
extern const char* const kComposite;

}  // namespace pfx_dof::shaders
