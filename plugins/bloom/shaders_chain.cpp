// The pyramid modes' programs: chain (the half-size pyramid) and chain13 (13-tap downsample, Karis average).
#include "bloom_shaders.hpp"
#include "shaders_common.hpp"

namespace pfx_bloom::shaders {
namespace {

// The bright programs cannot let the hardware filter the frame: one NaN texel poisons every
// bilinear tap that touches it, even with weight 0 (NaN * 0 = NaN), and from there the whole
// pyramid. So they fetch texels themselves, make each one safe, and only then filter in arithmetic
// as GL_LINEAR would (texel centres at +0.5), with clamp-to-border. All taps lie a whole number of
// texels from the centre, so they share one fraction f and read one square of texels, fetched once.
const char* const kTexelSquare = R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(location = 4) uniform vec3 u_gain;
layout(location = 5) uniform float u_cap;

// The N x N texels around this pixel's centre in the frame: t[y][x] is texel base + (x, y) - (N/2 - 1),
// so tap(t, N/2 - 1 + dx, N/2 - 1 + dy, f) is the bilinear tap dx, dy texels off the centre.
void fetch_square(out vec3 t[N][N], out vec2 f) {
  ivec2 size = textureSize(u_color, 0);
  vec2 q = gl_FragCoord.xy / u_out_size * vec2(size) - 0.5;
  vec2 base = floor(q);
  f = q - base;
  ivec2 i = ivec2(base) - (N / 2 - 1);
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) t[y][x] = safe_texel(u_color, i + ivec2(x, y), size);
}

vec3 tap(vec3 t[N][N], int x, int y, vec2 f) {
  return mix(mix(t[y][x], t[y][x + 1], f.x), mix(t[y + 1][x], t[y + 1][x + 1], f.x), f.y);
}
)glsl";

// The 3x3 tent from four bilinear taps half a source texel off the centre.
const char* const kTent = R"glsl(
vec3 tent(sampler2D s) {
  vec2 h = 0.5 / vec2(textureSize(s, 0));
  vec2 uv = gl_FragCoord.xy / u_out_size;
  return 0.25 * (texture(s, uv + vec2(-h.x, h.y)).rgb + texture(s, uv + vec2(h.x, h.y)).rgb +
                 texture(s, uv + vec2(h.x, -h.y)).rgb + texture(s, uv + vec2(-h.x, -h.y)).rgb);
}
)glsl";

}  // namespace

// The pyramid's five-tap bright pass: the centre (weight 4) and one texel off along each diagonal (weight 1),
// each tap's bright part, / 8. With u_karis each weight is also multiplied by the tap's Karis
// weight and the sum divided by the weights' sum.
std::string bright() {
  return std::string(kHeader) + "#define N 4\n" + kBrightCommon + kTexelSquare + R"glsl(
layout(location = 6) uniform int u_karis;

void main() {
  vec3 t[N][N];
  vec2 f;
  fetch_square(t, f);
  const ivec2 at[5] = ivec2[5](ivec2(1, 1), ivec2(0, 2), ivec2(2, 2), ivec2(0, 0), ivec2(2, 0));
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < 5; ++i) {
    vec3 p = bright_part(tap(t, at[i].x, at[i].y, f));
    float w = (i == 0 ? 4.0 : 1.0) * (u_karis != 0 ? karis_weight(p) : 1.0);
    sum += w * p;
    weights += w;
  }
  o_color = vec4(min(sum / weights * u_gain, vec3(u_cap)), 0.0);
}
)glsl";
}

// The sampler is the host's: linear, clamp-to-border (black) while going down.
std::string down() {
  return std::string(kHeader) + R"glsl(
layout(binding = 0) uniform sampler2D u_source;

void main() {
  const float offsets[4] = float[4](-2.75, -0.92, 0.92, 2.75);
  const float weights[4] = float[4](0.1087, 0.3913, 0.3913, 0.1087);
  vec2 texel = 1.0 / vec2(textureSize(u_source, 0));
  vec2 uv = gl_FragCoord.xy / u_out_size;
  vec3 sum = vec3(0.0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      sum += texture(u_source, uv + vec2(offsets[x], offsets[y]) * texel).rgb * (weights[x] * weights[y]);
  o_color = vec4(sum, 0.0);
}
)glsl";
}

// The sampler is the host's: linear, clamp-to-edge while going up. The host blends it (ONE, ONE)
// into the level below.
std::string up() {
  return std::string(kHeader) + "layout(binding = 0) uniform sampler2D u_source;\n" + kTent +
         "void main() { o_color = vec4(tent(u_source), 0.0); }\n";
}

// The last upsample, added to the frame here rather than by blending, so the frame's own bad values
// can be made finite too, and the sum stays at most 65504.
std::string composite() {
  return std::string(kHeader) + kFiniteFrame + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_level0;
)glsl" + kTent + R"glsl(
void main() {
  vec4 c = finite_frame(texelFetch(u_color, ivec2(gl_FragCoord.xy), 0));
  o_color = vec4(min(c.rgb + tent(u_level0), vec3(65504.0)), c.a);
}
)glsl";
}

// Jimenez's 13 taps, 0, 1 or 2 texels off the centre on each axis, read as five 4x4 boxes of four
// taps each: the centre box (the taps at +-1) weighted 0.5 and the four corner boxes 0.125 each.
// Each box is a Karis average of its taps' bright parts, weighted 1 / (1 + luma), so a lone firefly
// cannot outshine its neighbours.
std::string bright13() {
  return std::string(kHeader) + "#define N 6\n" + kBrightCommon + kTexelSquare + R"glsl(
vec3 karis(vec3 a, vec3 b, vec3 c, vec3 d) {
  float wa = karis_weight(a), wb = karis_weight(b), wc = karis_weight(c), wd = karis_weight(d);
  return (a * wa + b * wb + c * wc + d * wd) / (wa + wb + wc + wd);
}

void main() {
  vec3 t[N][N];
  vec2 f;
  fetch_square(t, f);
  vec3 p[5][5];  // p[dy + 2][dx + 2]: the bright part of the tap dx, dy texels off the centre
  for (int dy = 0; dy <= 4; dy += 1)
    for (int dx = 0; dx <= 4; dx += 1)
      if (((dx | dy) & 1) == 0 || ((dx & dy) & 1) == 1) p[dy][dx] = bright_part(tap(t, dx, dy, f));
  vec3 centre = karis(p[1][1], p[1][3], p[3][1], p[3][3]);
  vec3 corners = karis(p[0][0], p[0][2], p[2][0], p[2][2]) + karis(p[0][2], p[0][4], p[2][2], p[2][4]) +
                 karis(p[2][0], p[2][2], p[4][0], p[4][2]) + karis(p[2][2], p[2][4], p[4][2], p[4][4]);
  o_color = vec4(min((0.5 * centre + 0.125 * corners) * u_gain, vec3(u_cap)), 0.0);
}
)glsl";
}

// The same 13 taps on a level, plain averages (weights summed per tap), clamp-to-border sampler.
std::string down13() {
  return std::string(kHeader) + R"glsl(
layout(binding = 0) uniform sampler2D u_source;

vec3 at(vec2 uv, vec2 texel, float dx, float dy) { return texture(u_source, uv + vec2(dx, dy) * texel).rgb; }

void main() {
  vec2 texel = 1.0 / vec2(textureSize(u_source, 0));
  vec2 uv = gl_FragCoord.xy / u_out_size;
  vec3 inner = at(uv, texel, -1, -1) + at(uv, texel, 1, -1) + at(uv, texel, -1, 1) + at(uv, texel, 1, 1);
  vec3 cross = at(uv, texel, -2, 0) + at(uv, texel, 2, 0) + at(uv, texel, 0, -2) + at(uv, texel, 0, 2);
  vec3 outer = at(uv, texel, -2, -2) + at(uv, texel, 2, -2) + at(uv, texel, -2, 2) + at(uv, texel, 2, 2);
  vec3 sum = 0.125 * (inner + at(uv, texel, 0, 0)) + 0.0625 * cross + 0.03125 * outer;
  o_color = vec4(sum, 0.0);
}
)glsl";
}

}  // namespace pfx_bloom::shaders
