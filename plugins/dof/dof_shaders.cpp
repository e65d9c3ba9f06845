#include "dof_shaders.hpp"

#include <cstdio>

#include "dof_seed_disk.hpp"

namespace pfx_dof::shaders {

// Not-a-number and infinity are tested on the bits: a compiler may assume floats are finite and
// fold isnan() and isinf() away.
const char* const kCommon = R"glsl(#version 450 core
layout(location = 0) uniform int u_encoding;
layout(location = 1) uniform vec2 u_planes;
layout(location = 2) uniform int u_far_infinite;
layout(location = 3) uniform float u_max_coc;
layout(location = 30) uniform int u_nonfinite;  // Nonfinite (dof_params.hpp)
layout(location = 0) out vec4 o_color;

const float k_half_max = 65504.0;

bool is_nan(float v) { return (floatBitsToUint(v) & 0x7fffffffu) > 0x7f800000u; }
bool is_inf(float v) { return (floatBitsToUint(v) & 0x7fffffffu) == 0x7f800000u; }
float infinity() { return uintBitsToFloat(0x7f800000u); }

// nonfinite zero: a pixel with NaN or +-Inf in R, G or B is black and a non-finite alpha 0 (alone);
// clamp: NaN -> 0 per channel, +-Inf to +-65504 by the clamp.
vec4 safe_color(vec4 c) {
  uvec4 bits = floatBitsToUint(c) & uvec4(0x7fffffffu);
  if (u_nonfinite == 0) {
    if (any(greaterThanEqual(bits.rgb, uvec3(0x7f800000u)))) c.rgb = vec3(0.0);
    if (bits.a >= 0x7f800000u) c.a = 0.0;
  }
  bvec4 nan = greaterThan(bits, uvec4(0x7f800000u));
  return clamp(mix(c, vec4(0.0), nan), vec4(-k_half_max), vec4(k_half_max));
}

// pfx_view_depth (pfx/depth.h): 1 standard hardware, 2 reversed, 3 linear metres.
float view_depth(float stored) {
  if (u_encoding == 3) return stored;
  float n = u_planes.x, f = u_planes.y;
  if (u_encoding == 1) {
    float z = 2.0 * stored - 1.0;
    if (u_far_infinite != 0) return z >= 1.0 ? infinity() : 2.0 * n / (1.0 - z);
    float denom = (f + n) - z * (f - n);
    return denom <= 0.0 ? infinity() : 2.0 * n * f / denom;
  }
  if (stored < 0.0) return infinity();
  if (u_far_infinite != 0) return stored == 0.0 ? infinity() : n / stored;
  return n * f / (stored * (f - n) + n);
}

// Signed CoC diameter in frame pixels (dof_camera.hpp: C (1/P - 1/D), clamped; NaN depth -> 0,
// depth <= 0 -> the nearest blur).
float coc_of(vec2 lens, float depth) {
  if (is_nan(depth)) return 0.0;
  if (depth <= 0.0) return -u_max_coc;
  float inverse = is_inf(depth) ? 0.0 : 1.0 / depth;
  return clamp(lens.x * (lens.y - inverse), -u_max_coc, u_max_coc);
}
)glsl";

const char* const kLens = R"glsl(
layout(binding = 0) uniform sampler2D u_depth;
layout(location = 4) uniform vec4 u_camera;
layout(location = 5) uniform ivec2 u_focus_texel;
layout(location = 6) uniform int u_autofocus;
layout(location = 7) uniform vec2 u_focus_range;

void main() {
  float p = u_camera.w;
  if (u_autofocus != 0) {
    float d = view_depth(texelFetch(u_depth, u_focus_texel, 0).r);
    if (!is_nan(d)) p = clamp(d, u_focus_range.x, u_focus_range.y);
  }
  float image_distance = u_camera.x, inverse_focus = 1.0 / p;
  float scale = image_distance * image_distance * u_camera.y / (u_camera.z * (1000.0 + image_distance * inverse_focus));
  o_color = vec4(scale, inverse_focus, 0.0, 0.0);
}
)glsl";

// Bilinear by hand from four safe texels: one NaN texel would poison GL_LINEAR's mix.
const char* const kSeedHalf = R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(location = 4) uniform vec2 u_out_size;

void main() {
  ivec2 size = textureSize(u_color, 0);
  vec2 q = gl_FragCoord.xy / u_out_size * vec2(size) - 0.5;
  vec2 base = floor(q), f = q - base;
  ivec2 i = ivec2(base), hi = size - 1;
  vec4 a = safe_color(texelFetch(u_color, clamp(i, ivec2(0), hi), 0));
  vec4 b = safe_color(texelFetch(u_color, clamp(i + ivec2(1, 0), ivec2(0), hi), 0));
  vec4 c = safe_color(texelFetch(u_color, clamp(i + ivec2(0, 1), ivec2(0), hi), 0));
  vec4 d = safe_color(texelFetch(u_color, clamp(i + ivec2(1, 1), ivec2(0), hi), 0));
  o_color = mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}
)glsl";

std::string seed_body() {
  std::string disk;
  for (int i = 0; i < kSeedTaps; ++i) {
    char item[64];
    std::snprintf(item, sizeof item, "%svec2(%.3f, %.3f)", i ? ", " : "", kSeedDisk[i][0], kSeedDisk[i][1]);
    disk += item;
  }
  return "const vec2 k_disk[16] = vec2[16](" + disk + ");\n" + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_depth;
layout(binding = 2) uniform sampler2D u_half;
layout(binding = 3) uniform sampler2D u_lens;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 size = vec2(textureSize(u_color, 0));
  vec4 sharp = safe_color(texelFetch(u_color, p, 0));
  float coc = abs(coc_of(texelFetch(u_lens, ivec2(0), 0).xy, view_depth(texelFetch(u_depth, p, 0).r)));
  o_color = sharp;
  if (coc > 1.0) {
    vec2 uv = gl_FragCoord.xy / size, scale = coc / size;
    vec3 blur = vec3(0.0);
    for (int i = 0; i < 16; ++i) blur += texture(u_half, uv + k_disk[i] * scale).rgb;
    o_color.rgb = mix(sharp.rgb, blur * (1.0 / 16.0), clamp(coc - 1.0, 0.0, 1.0));
  }
}
)glsl";
}

}  // namespace pfx_dof::shaders

namespace pfx_dof::shaders {

const char* const kPrepare = R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_depth;
layout(binding = 2) uniform sampler2D u_lens;
layout(location = 4) uniform int u_half;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 lens = texelFetch(u_lens, ivec2(0), 0).xy;
  if (u_half == 0) {
    o_color = vec4(safe_color(texelFetch(u_color, p, 0)).rgb, coc_of(lens, view_depth(texelFetch(u_depth, p, 0).r)));
    return;
  }
  // The block's mean colour; its nearest CoC, so a foreground edge keeps its reach. One bilinear
  // tap at the block's corner weighs its four texels 1/4 each (clamped at odd edges as a fetch
  // is), and one gather reads its four depths; only a block holding NaN or Inf is read texel by
  // texel, to make each safe first.
  ivec2 size = textureSize(u_color, 0), hi = size - 1;
  vec2 uv = vec2(2 * p + 1) / vec2(size);
  vec3 sum = 4.0 * texture(u_color, uv).rgb;
  if (any(greaterThanEqual(floatBitsToUint(sum) & uvec3(0x7fffffffu), uvec3(0x7f800000u)))) {
    sum = vec3(0.0);
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) sum += safe_color(texelFetch(u_color, min(2 * p + ivec2(i, j), hi), 0)).rgb;
  }
  vec4 depths = textureGather(u_depth, uv, 0);
  float nearest = min(min(coc_of(lens, view_depth(depths.x)), coc_of(lens, view_depth(depths.y))),
                      min(coc_of(lens, view_depth(depths.z)), coc_of(lens, view_depth(depths.w))));
  o_color = vec4(sum * 0.25, nearest);
}
)glsl";

const char* const kTiles = R"glsl(
layout(binding = 0) uniform sampler2D u_work;
layout(location = 4) uniform int u_tile;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy), size = textureSize(u_work, 0);
  float near = 0.0, reach = 0.0;
  for (int y = 0; y < u_tile; ++y)
    for (int x = 0; x < u_tile; ++x) {
      ivec2 q = t * u_tile + ivec2(x, y);
      if (q.x >= size.x || q.y >= size.y) continue;
      float coc = texelFetch(u_work, q, 0).a;
      near = max(near, -coc);
      reach = max(reach, abs(coc));
    }
  o_color = vec4(near, reach, 0.0, 0.0);
}
)glsl";

const char* const kDilate = R"glsl(
layout(binding = 0) uniform sampler2D u_tiles;
layout(location = 5) uniform int u_dilation;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy), hi = textureSize(u_tiles, 0) - 1;
  float near = 0.0;
  for (int y = -u_dilation; y <= u_dilation; ++y)
    for (int x = -u_dilation; x <= u_dilation; ++x)
      near = max(near, texelFetch(u_tiles, clamp(t + ivec2(x, y), ivec2(0), hi), 0).r);
  o_color = vec4(near, texelFetch(u_tiles, t, 0).g, 0.0, 0.0);
}
)glsl";

// Scatter as gather, in two fields (docs/effects/dof.md). A sample in front of the pixel (smaller
// CoC) is near: it covers the pixel if its own blur reaches it, with the density of its own disc,
// and the summed coverage is the near field's alpha. Every other sample is far: it counts only
// within the pixel's own blur radius, so a sharp pixel takes nothing from a blurred background
// behind it and a blurred background takes nothing from a sharp object in front (no halo).
const char* const kGather = R"glsl(
layout(binding = 0) uniform sampler2D u_work;
layout(binding = 1) uniform sampler2D u_dilated;
layout(binding = 2) uniform sampler2D u_color;
// [0, 256): ring samples (x, y, area); [256, 512): disc offsets nearest first (x, y, length).
layout(std430, binding = 0) readonly buffer Samples { vec4 u_samples[]; };
layout(location = 4) uniform int u_sample_count;
layout(location = 5) uniform float u_scale;
layout(location = 6) uniform int u_tile;
layout(location = 7) uniform int u_full;

float coverage(float d, float r) { return clamp(r - d + 0.5, 0.0, 1.0); }
float density(float r) { return 1.0 / (3.14159265358979 * (r * r + 1.0 / 12.0)); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy), hi = textureSize(u_work, 0) - 1;
  vec2 tile = texelFetch(u_dilated, p / u_tile, 0).rg;
  float reach = max(tile.r, tile.g);
  vec4 center = texelFetch(u_work, p, 0);
  if (reach < 1.0) {  // in focus, and no blurred foreground can reach: skip all gather work
    o_color = u_full != 0 ? safe_color(texelFetch(u_color, p, 0)) : vec4(center.rgb, 1.0);
    return;
  }
  // A sample that covers this pixel from in front is either near (its reach is the tile's dilated
  // near CoC) or nearer to the focus than the pixel (so less blurred); a far sample counts only
  // within the pixel's own radius. So the rings need reach no further than the larger of the two.
  float r_p = max(0.5 * abs(center.a) * u_scale, 0.5);
  float radius = max(r_p, 0.5 * tile.r * u_scale);
  float far_weight = density(r_p);
  vec3 far_sum = center.rgb * far_weight;
  vec3 near_sum = vec3(0.0);
  float near_weight = 0.0;
  // Every texel of the disc when they fit in the budget, else the rings scaled to the radius.
  bool whole_disc = u_sample_count >= 256 || u_samples[256 + u_sample_count].z >= radius + 0.5;
  for (int i = 0; i < u_sample_count; ++i) {
    ivec2 o;
    float area;
    if (whole_disc) {
      vec4 s = u_samples[256 + i];
      if (s.z >= radius + 0.5) break;
      o = ivec2(s.xy);
      area = 1.0;
    } else {
      vec4 s = u_samples[i];
      o = ivec2(floor(s.xy * radius + 0.5));
      if (o == ivec2(0)) continue;
      area = s.z * radius * radius;
    }
    float d = length(vec2(o));
    vec4 q = texelFetch(u_work, clamp(p + o, ivec2(0), hi), 0);
    if (q.a < center.a) {
      float r_q = max(0.5 * abs(q.a) * u_scale, 0.5);
      float w = area * coverage(d, r_q) * density(r_q);
      near_sum += w * q.rgb;
      near_weight += w;
    } else {
      float w = area * coverage(d, r_p) * density(r_p);
      far_sum += w * q.rgb;
      far_weight += w;
    }
  }
  float alpha = min(near_weight, 1.0);
  vec3 near = near_weight > 0.0 ? near_sum / near_weight : vec3(0.0);
  vec3 result = mix(far_sum / far_weight, near, alpha);
  o_color = u_full != 0 ? vec4(result, safe_color(texelFetch(u_color, p, 0)).a) : vec4(result, 1.0 - alpha);
}
)glsl";

// Upsampling weighs the four half texels around the pixel by how close their CoC is to the
// pixel's own, so a blurred background's texels do not leak into a sharp edge (and back). The
// sharp pixel replaces the half-resolution one where the pixel's CoC is under 1 px, behind what
// the near field covers: out = blur + visible * (1 - t) * (sharp - half).
const char* const kComposite = R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_depth;
layout(binding = 2) uniform sampler2D u_lens;
layout(binding = 3) uniform sampler2D u_work;
layout(binding = 4) uniform sampler2D u_blur;
layout(binding = 5) uniform sampler2D u_dilated;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 sharp = safe_color(texelFetch(u_color, p, 0));
  vec2 tile = texelFetch(u_dilated, p / 16, 0).rg;
  if (max(tile.r, tile.g) < 1.0) {
    o_color = sharp;
    return;
  }
  // Where the four half texels hold one smooth surface (their CoCs within a quarter of the
  // weighting's scale), CoC weights would change little: plain bilinear taps do, and the pixel's
  // CoC is theirs interpolated, so neither the depth nor the lens is read. Fully blurred pixels
  // need only the blur: 4 fetches instead of 12.
  vec2 h = vec2(p) * 0.5 - 0.25;
  vec2 base = floor(h), f = h - base;
  vec2 uv = (vec2(p) * 0.5 + 0.25) / vec2(textureSize(u_work, 0));
  vec4 cocs = textureGather(u_work, uv, 3);  // (x0, y1), (x1, y1), (x1, y0), (x0, y0)
  float coc = mix(mix(cocs.w, cocs.z, f.x), mix(cocs.x, cocs.y, f.x), f.y);
  float spread = max(max(cocs.x, cocs.y), max(cocs.z, cocs.w)) - min(min(cocs.x, cocs.y), min(cocs.z, cocs.w));
  if (spread <= 0.25 * (1.0 + 0.25 * abs(coc))) {
    float t = clamp(abs(coc) - 1.0, 0.0, 1.0);
    vec4 blur = texture(u_blur, uv);
    vec3 rgb = blur.rgb;
    if (t < 1.0) rgb += blur.a * (1.0 - t) * (sharp.rgb - texture(u_work, uv).rgb);
    o_color = vec4(rgb, sharp.a);
    return;
  }
  coc = coc_of(texelFetch(u_lens, ivec2(0), 0).xy, view_depth(texelFetch(u_depth, p, 0).r));
  float t = clamp(abs(coc) - 1.0, 0.0, 1.0);
  ivec2 b = ivec2(base), hi = textureSize(u_work, 0) - 1;
  vec4 blur = vec4(0.0);
  vec3 half_color = vec3(0.0);
  float total = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 q = clamp(b + ivec2(i, j), ivec2(0), hi);
      vec4 work = texelFetch(u_work, q, 0);
      float bilinear = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
      float w = bilinear * max(1e-3, 1.0 - abs(work.a - coc) / (1.0 + 0.25 * abs(coc)));
      blur += w * texelFetch(u_blur, q, 0);
      half_color += w * work.rgb;
      total += w;
    }
  blur /= total;
  half_color /= total;
  o_color = vec4(blur.rgb + blur.a * (1.0 - t) * (sharp.rgb - half_color), sharp.a);
}
)glsl";

}  // namespace pfx_dof::shaders
