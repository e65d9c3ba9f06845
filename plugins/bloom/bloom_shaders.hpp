// GLSL of the bloom and glare programs. Every program is the shared full-screen vertex shader and
// one of these fragment shaders. Uniform locations: 0 is always the output size (vec2); the bright
// programs share 1 (threshold, knee), 2 (measure), 3 (firefly clamp) from kBrightCommon; the rest
// are listed with each and set in the *_passes.cpp file that runs it.
#pragma once

#include <string>

namespace pfx_bloom::shaders {

// chain: frame -> level 0. 4: vec3 gain (strength / levels * tint), 5: float cap per level.
std::string bright();
// chain: level i-1 -> level i, the pyramid's 4x4 bilinear taps (8x8 texels).
std::string down();
// chain, chain13: level i+1 -> added into level i, the 3x3 tent from four half-texel taps.
std::string up();
// chain, chain13: frame + tent-upsampled level 0 -> output.
std::string composite();
// chain13: frame -> level 0, 13 taps with a Karis average. 4: vec3 gain, 5: float cap.
std::string bright13();
// chain13: level i-1 -> level i, 13 bilinear taps.
std::string down13();
// gaussian, mgf, glare: frame -> a buffer 1/block the size, each texel the mean bright part of a
// block x block square of pixels. 4: int block, 5: vec3 gain, 6: float cap.
std::string box_bright();
// gaussian, mgf: one direction of a separable Gaussian. 4: ivec2 direction (1,0) or (0,1),
// 5: int taps on each side, 6..: float weights[centre, 1, 2 ...].
std::string blur();
// gaussian: frame * tone + bilinear bloom -> output. 4: float tone scale, 5: int has bloom.
std::string gaussian_composite();
// mgf: frame + sum of weighted buffers -> output. 4: int count, 5..: float weights[count].
std::string mgf_composite();
// glare: one pass of one streak, 16 taps. 4: vec2 step (uv between taps: direction * b / size),
// 5: float weights[16] (normalised a^(b*s), divided by the streak count in the last pass).
std::string streak();
// glare: frame + gain * bilinear streaks -> output. 4: vec3 gain (strength * tint).
std::string glare_composite();

}  // namespace pfx_bloom::shaders
