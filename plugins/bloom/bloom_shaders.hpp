// GLSL of the "chain" mode's four programs. Uniform locations are listed with each, and are what
// bloom_effect.cpp sets.
#pragma once

namespace pfx_bloom::shaders {

// Frame colour -> level 0. 0: vec2 output size, 1: vec2 (threshold, knee), 2: int measure,
// 3: float firefly clamp, 4: vec3 gain (strength / levels * tint), 5: float cap per level.
extern const char* const kBright;
// Level i-1 -> level i, the seed's 4x4 bilinear taps (8x8 texels). 0: vec2 output size.
extern const char* const kDown;
// Level i+1 -> added into level i, the 3x3 tent from four half-texel taps. 0: vec2 output size.
extern const char* const kUp;
// Frame colour + tent-upsampled level 0 -> output. 0: vec2 output size.
extern const char* const kComposite;

}  // namespace pfx_bloom::shaders
