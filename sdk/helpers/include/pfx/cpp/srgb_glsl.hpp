// The exact piecewise sRGB curves (IEC 61966-2-1) as GLSL functions, in one place for every
// program that moves colour between display-referred 8-bit values and linear light: the hosts'
// transfer programs and the FX plugin's back buffer. In 32-bit float they put every 8-bit code
// back on itself.
#pragma once

namespace pfx::gl {

// vec3 pfx_srgb_decode(vec3 display) -> linear; vec3 pfx_srgb_encode(vec3 linear) -> display.
inline const char* srgb_glsl_functions() {
  return "vec3 pfx_srgb_decode(vec3 v) {\n"
         "  return mix(v / 12.92, pow((v + 0.055) / 1.055, vec3(2.4)), greaterThan(v, vec3(0.04045)));\n"
         "}\n"
         "vec3 pfx_srgb_encode(vec3 v) {\n"
         "  return mix(v * 12.92, 1.055 * pow(v, vec3(1.0 / 2.4)) - 0.055, greaterThan(v, vec3(0.0031308)));\n"
         "}\n";
}

}  // namespace pfx::gl
