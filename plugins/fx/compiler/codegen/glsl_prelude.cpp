// The GLSL helper functions generated code calls where HLSL's meaning has no single GLSL
// built-in. Only the helpers a program uses are emitted.
#include <string>

#include "glsl_writer.hpp"

namespace pfx::fx {
namespace {

// `pattern` once per type of a family, with T the type, B the bool and I the int type of its shape.
std::string each(const std::string& pattern, std::initializer_list<const char*> types, std::initializer_list<const char*> bools,
                 std::initializer_list<const char*> ints) {
  std::string out;
  auto b = bools.begin();
  auto i = ints.begin();
  for (const char* t : types) {
    std::string text = pattern;
    for (std::size_t at; (at = text.find("$T")) != std::string::npos;) text.replace(at, 2, t);
    for (std::size_t at; (at = text.find("$B")) != std::string::npos;) text.replace(at, 2, *b);
    for (std::size_t at; (at = text.find("$I")) != std::string::npos;) text.replace(at, 2, *i);
    out += text;
    ++b, ++i;
  }
  return out;
}

const std::initializer_list<const char*> kFloats = {"float", "vec2", "vec3", "vec4"};
const std::initializer_list<const char*> kBools = {"bool", "bvec2", "bvec3", "bvec4"};
const std::initializer_list<const char*> kInts = {"int", "ivec2", "ivec3", "ivec4"};

}  // namespace

std::string prelude(const std::set<std::string>& helpers, GlslDialect dialect) {
  std::string out;
  auto wants = [&](const char* name) { return helpers.count(name) > 0; };
  if (wants("flip") && dialect == GlslDialect::kVulkan) {
    // Vulkan's rows run as FX's: the same calls, which the compiler folds away.
    out += "vec2 pfx_flip(vec2 c) { return c; }\n"
           "vec3 pfx_flip(vec3 c) { return c; }\n"
           "ivec2 pfx_flip_texel(ivec2 c, int h) { return c; }\n"
           "ivec3 pfx_flip_texel(ivec3 c, int h) { return c; }\n"
           "vec2 pfx_flip_offset(vec2 o) { return o; }\n"
           "vec3 pfx_flip_offset(vec3 o) { return o; }\n";
  } else if (wants("flip")) {
    // Texture rows: GL counts from the bottom, FX from the top.
    out += "vec2 pfx_flip(vec2 c) { return vec2(c.x, 1.0 - c.y); }\n"
           "vec3 pfx_flip(vec3 c) { return vec3(c.x, 1.0 - c.y, c.z); }\n"
           "ivec2 pfx_flip_texel(ivec2 c, int h) { return ivec2(c.x, h - 1 - c.y); }\n"
           "ivec3 pfx_flip_texel(ivec3 c, int h) { return ivec3(c.x, h - 1 - c.y, c.z); }\n"
           "vec2 pfx_flip_offset(vec2 o) { return vec2(o.x, -o.y); }\n"
           "vec3 pfx_flip_offset(vec3 o) { return vec3(o.x, -o.y, o.z); }\n";
  }
  // HLSL fmod and float '%': the remainder of truncated division, with the sign of x.
  if (wants("fmod")) out += each("$T pfx_fmod($T x, $T y) { return x - y * trunc(x / y); }\n", kFloats, kBools, kInts);
  // HLSL int '%': truncated, like C. GLSL leaves negative operands undefined.
  if (wants("imod")) out += each("$T pfx_imod($T x, $T y) { return x - y * (x / y); }\n", kInts, kBools, kInts);
  if (wants("logic")) {
    out += each("$B pfx_and($B a, $B b) { return $B($I(a) & $I(b)); }\n", {"bvec2", "bvec3", "bvec4"}, {"bvec2", "bvec3", "bvec4"}, {"ivec2", "ivec3", "ivec4"});
    out += each("$B pfx_or($B a, $B b) { return $B($I(a) | $I(b)); }\n", {"bvec2", "bvec3", "bvec4"}, {"bvec2", "bvec3", "bvec4"}, {"ivec2", "ivec3", "ivec4"});
  }
  if (wants("isfinite")) {
    out += "bool pfx_isfinite(float x) { return !(isnan(x) || isinf(x)); }\n";
    out += each("$B pfx_isfinite($T x) { return not($B($I(isnan(x)) | $I(isinf(x)))); }\n", {"vec2", "vec3", "vec4"}, {"bvec2", "bvec3", "bvec4"}, {"ivec2", "ivec3", "ivec4"});
  }
  if (wants("clip")) {
    out += "void pfx_clip(float x) { if (x < 0.0) discard; }\n";
    out += each("void pfx_clip($T x) { if (any(lessThan(x, $T(0.0)))) discard; }\n", {"vec2", "vec3", "vec4"}, kBools, kInts);
  }
  if (wants("half")) {
    out += "float pfx_f16tof32(uint x) { return unpackHalf2x16(x).x; }\n"
           "vec2 pfx_f16tof32(uvec2 x) { return vec2(pfx_f16tof32(x.x), pfx_f16tof32(x.y)); }\n"
           "vec3 pfx_f16tof32(uvec3 x) { return vec3(pfx_f16tof32(x.xy), pfx_f16tof32(x.z)); }\n"
           "vec4 pfx_f16tof32(uvec4 x) { return vec4(pfx_f16tof32(x.xy), pfx_f16tof32(x.zw)); }\n"
           "uint pfx_f32tof16(float x) { return packHalf2x16(vec2(x, 0.0)) & 0xFFFFu; }\n"
           "uvec2 pfx_f32tof16(vec2 x) { return uvec2(pfx_f32tof16(x.x), pfx_f32tof16(x.y)); }\n"
           "uvec3 pfx_f32tof16(vec3 x) { return uvec3(pfx_f32tof16(x.xy), pfx_f32tof16(x.z)); }\n"
           "uvec4 pfx_f32tof16(vec4 x) { return uvec4(pfx_f32tof16(x.xy), pfx_f32tof16(x.zw)); }\n";
  }
  // HLSL's float to int and uint (ftoi, ftou): toward zero, saturated at the type's range, NaN
  // to 0 (every comparison with NaN is false). GLSL leaves a value out of range undefined.
  if (wants("ftoi")) {
    out += "int pfx_ftoi(float x) { return x >= 2147483648.0 ? 2147483647 : x > -2147483648.0 ? int(x) : x < 0.0 ? (-2147483647 - 1) : 0; }\n";
    out += each("$I pfx_ftoi($T x) { return mix(mix(mix($I(0), $I(-2147483647 - 1), lessThan(x, $T(0.0))), $I(x), "
                "greaterThan(x, $T(-2147483648.0))), $I(2147483647), greaterThanEqual(x, $T(2147483648.0))); }\n",
                {"vec2", "vec3", "vec4"}, kBools, {"ivec2", "ivec3", "ivec4"});
  }
  if (wants("ftou")) {
    out += "uint pfx_ftou(float x) { return x >= 4294967296.0 ? 4294967295u : x > 0.0 ? uint(x) : 0u; }\n";
    out += each("$I pfx_ftou($T x) { return mix(mix($I(0u), $I(x), greaterThan(x, $T(0.0))), $I(4294967295u), "
                "greaterThanEqual(x, $T(4294967296.0))); }\n",
                {"vec2", "vec3", "vec4"}, kBools, {"uvec2", "uvec3", "uvec4"});
  }
  // HLSL's frexp gives the exponent as a float.
  if (wants("frexp")) out += each("$T pfx_frexp($T x, out $T e) { $I i; $T m = frexp(x, i); e = $T(i); return m; }\n", kFloats, kBools, kInts);
  return out;
}

}  // namespace pfx::fx
