// GLSL pieces the bloom and glare fragment shaders are assembled from (shaders_common.cpp).
#pragma once

namespace pfx_bloom::shaders {

extern const char* const kHeader;        // version, u_out_size (location 0), o_color
extern const char* const kBrightCommon;  // locations 1-3; safe_color, safe_texel, bright_part
extern const char* const kFiniteFrame;   // finite_frame(vec4)

}  // namespace pfx_bloom::shaders
