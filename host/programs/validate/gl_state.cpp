#include "gl_state.hpp"

#include <cstdio>

#include <glad/gl.h>

namespace pfx::validate {
namespace {

enum class Kind { Enable, Integer, Integer4, ColorMask0, Enum };

struct Entry {
  const char* name;
  GLenum pname;
  Kind kind;
};

#define PFX_GL_ENTRY(pname, kind) {#pname, pname, Kind::kind}
// The contract's "leave as found" list: framebuffer, vertex-array, pipeline, transform feedback
// and pixel/query buffer bindings, the viewport, the colour mask of draw buffer 0, blend equation
// and function, the raster, depth and stencil settings the host sets once per frame, the pixel
// store, and the enables. The contract says "any other enable you touch" too, so every
// capability a post pass could plausibly switch is here.
const Entry kEntries[] = {
    PFX_GL_ENTRY(GL_DRAW_FRAMEBUFFER_BINDING, Integer),
    PFX_GL_ENTRY(GL_READ_FRAMEBUFFER_BINDING, Integer),
    PFX_GL_ENTRY(GL_VERTEX_ARRAY_BINDING, Integer),
    PFX_GL_ENTRY(GL_VIEWPORT, Integer4),
    PFX_GL_ENTRY(GL_COLOR_WRITEMASK, ColorMask0),
    PFX_GL_ENTRY(GL_BLEND_EQUATION_RGB, Enum),
    PFX_GL_ENTRY(GL_BLEND_EQUATION_ALPHA, Enum),
    PFX_GL_ENTRY(GL_BLEND_SRC_RGB, Enum),
    PFX_GL_ENTRY(GL_BLEND_DST_RGB, Enum),
    PFX_GL_ENTRY(GL_BLEND_SRC_ALPHA, Enum),
    PFX_GL_ENTRY(GL_BLEND_DST_ALPHA, Enum),
    PFX_GL_ENTRY(GL_BLEND, Enable),
    PFX_GL_ENTRY(GL_DEPTH_TEST, Enable),
    PFX_GL_ENTRY(GL_STENCIL_TEST, Enable),
    PFX_GL_ENTRY(GL_SCISSOR_TEST, Enable),
    PFX_GL_ENTRY(GL_CULL_FACE, Enable),
    PFX_GL_ENTRY(GL_POLYGON_OFFSET_FILL, Enable),
    PFX_GL_ENTRY(GL_FRAMEBUFFER_SRGB, Enable),
    PFX_GL_ENTRY(GL_RASTERIZER_DISCARD, Enable),
    PFX_GL_ENTRY(GL_COLOR_LOGIC_OP, Enable),
    PFX_GL_ENTRY(GL_SAMPLE_ALPHA_TO_COVERAGE, Enable),
    PFX_GL_ENTRY(GL_SAMPLE_COVERAGE, Enable),
    PFX_GL_ENTRY(GL_SAMPLE_SHADING, Enable),
    PFX_GL_ENTRY(GL_MULTISAMPLE, Enable),
    PFX_GL_ENTRY(GL_DEPTH_CLAMP, Enable),
    PFX_GL_ENTRY(GL_PRIMITIVE_RESTART, Enable),
    PFX_GL_ENTRY(GL_PRIMITIVE_RESTART_FIXED_INDEX, Enable),
    PFX_GL_ENTRY(GL_PROGRAM_POINT_SIZE, Enable),
    PFX_GL_ENTRY(GL_DITHER, Enable),
    PFX_GL_ENTRY(GL_CLIP_DISTANCE0, Enable),
    PFX_GL_ENTRY(GL_SAMPLE_ALPHA_TO_ONE, Enable),
    PFX_GL_ENTRY(GL_SAMPLE_MASK, Enable),
    PFX_GL_ENTRY(GL_POLYGON_OFFSET_LINE, Enable),
    PFX_GL_ENTRY(GL_POLYGON_OFFSET_POINT, Enable),
    PFX_GL_ENTRY(GL_POLYGON_SMOOTH, Enable),
    PFX_GL_ENTRY(GL_LINE_SMOOTH, Enable),
    PFX_GL_ENTRY(GL_TEXTURE_CUBE_MAP_SEAMLESS, Enable),
    PFX_GL_ENTRY(GL_PROGRAM_PIPELINE_BINDING, Integer),
    PFX_GL_ENTRY(GL_TRANSFORM_FEEDBACK_BINDING, Integer),
    PFX_GL_ENTRY(GL_PIXEL_PACK_BUFFER_BINDING, Integer),
    PFX_GL_ENTRY(GL_PIXEL_UNPACK_BUFFER_BINDING, Integer),
    PFX_GL_ENTRY(GL_QUERY_BUFFER_BINDING, Integer),
    PFX_GL_ENTRY(GL_POLYGON_MODE, Enum),
    PFX_GL_ENTRY(GL_CLIP_ORIGIN, Enum),
    PFX_GL_ENTRY(GL_CLIP_DEPTH_MODE, Enum),
    PFX_GL_ENTRY(GL_PROVOKING_VERTEX, Enum),
    PFX_GL_ENTRY(GL_CULL_FACE_MODE, Enum),
    PFX_GL_ENTRY(GL_FRONT_FACE, Enum),
    PFX_GL_ENTRY(GL_DEPTH_FUNC, Enum),
    PFX_GL_ENTRY(GL_DEPTH_WRITEMASK, Integer),
    PFX_GL_ENTRY(GL_STENCIL_FUNC, Enum),
    PFX_GL_ENTRY(GL_STENCIL_FAIL, Enum),
    PFX_GL_ENTRY(GL_STENCIL_PASS_DEPTH_FAIL, Enum),
    PFX_GL_ENTRY(GL_STENCIL_PASS_DEPTH_PASS, Enum),
    PFX_GL_ENTRY(GL_STENCIL_WRITEMASK, Integer),
    PFX_GL_ENTRY(GL_CLAMP_READ_COLOR, Enum),
    PFX_GL_ENTRY(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, Enum),
    PFX_GL_ENTRY(GL_PATCH_VERTICES, Integer),
    PFX_GL_ENTRY(GL_UNPACK_ALIGNMENT, Integer),
    PFX_GL_ENTRY(GL_UNPACK_ROW_LENGTH, Integer),
    PFX_GL_ENTRY(GL_UNPACK_IMAGE_HEIGHT, Integer),
    PFX_GL_ENTRY(GL_UNPACK_SKIP_PIXELS, Integer),
    PFX_GL_ENTRY(GL_UNPACK_SKIP_ROWS, Integer),
    PFX_GL_ENTRY(GL_UNPACK_SKIP_IMAGES, Integer),
    PFX_GL_ENTRY(GL_UNPACK_SWAP_BYTES, Integer),
    PFX_GL_ENTRY(GL_PACK_ALIGNMENT, Integer),
    PFX_GL_ENTRY(GL_PACK_ROW_LENGTH, Integer),
    PFX_GL_ENTRY(GL_PACK_IMAGE_HEIGHT, Integer),
    PFX_GL_ENTRY(GL_PACK_SKIP_PIXELS, Integer),
    PFX_GL_ENTRY(GL_PACK_SKIP_ROWS, Integer),
    PFX_GL_ENTRY(GL_PACK_SKIP_IMAGES, Integer),
    PFX_GL_ENTRY(GL_PACK_SWAP_BYTES, Integer),
};
#undef PFX_GL_ENTRY

std::string enum_text(long value) {
  switch (value) {
    case GL_ZERO: return "GL_ZERO";
    case GL_ONE: return "GL_ONE";
    case GL_SRC_ALPHA: return "GL_SRC_ALPHA";
    case GL_ONE_MINUS_SRC_ALPHA: return "GL_ONE_MINUS_SRC_ALPHA";
    case GL_DST_ALPHA: return "GL_DST_ALPHA";
    case GL_ONE_MINUS_DST_ALPHA: return "GL_ONE_MINUS_DST_ALPHA";
    case GL_SRC_COLOR: return "GL_SRC_COLOR";
    case GL_DST_COLOR: return "GL_DST_COLOR";
    case GL_FUNC_ADD: return "GL_FUNC_ADD";
    case GL_FUNC_SUBTRACT: return "GL_FUNC_SUBTRACT";
    case GL_FUNC_REVERSE_SUBTRACT: return "GL_FUNC_REVERSE_SUBTRACT";
    case GL_MIN: return "GL_MIN";
    case GL_MAX: return "GL_MAX";
    case GL_FILL: return "GL_FILL";
    case GL_LINE: return "GL_LINE";
    case GL_POINT: return "GL_POINT";
    case GL_LOWER_LEFT: return "GL_LOWER_LEFT";
    case GL_UPPER_LEFT: return "GL_UPPER_LEFT";
    default: {
      char buffer[24];
      std::snprintf(buffer, sizeof buffer, "0x%04lx", static_cast<unsigned long>(value));
      return buffer;
    }
  }
}

std::string values_text(const Entry& entry, const std::vector<long>& values) {
  if (entry.kind == Kind::Enable) return values[0] ? "enabled" : "disabled";
  if (entry.kind == Kind::Enum) return enum_text(values[0]);
  std::string text;
  for (size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + std::to_string(values[i]);
  return values.size() > 1 ? "(" + text + ")" : text;
}

}  // namespace

GlStateSnapshot snapshot_gl_state() {
  GlStateSnapshot snapshot;
  for (const Entry& entry : kEntries) {
    GlStateValue value{entry.name, {}};
    switch (entry.kind) {
      case Kind::Enable:
        value.values = {glIsEnabled(entry.pname) ? 1L : 0L};
        break;
      case Kind::Integer:
      case Kind::Enum: {
        GLint v[4] = {0, 0, 0, 0};  // GL_POLYGON_MODE writes two
        glGetIntegerv(entry.pname, v);
        value.values = {static_cast<long>(v[0])};
        break;
      }
      case Kind::Integer4: {
        GLint v[4] = {0, 0, 0, 0};
        glGetIntegerv(entry.pname, v);
        value.values = {v[0], v[1], v[2], v[3]};
        break;
      }
      case Kind::ColorMask0: {
        GLboolean m[4] = {GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE};
        glGetBooleani_v(entry.pname, 0, m);
        value.values = {m[0], m[1], m[2], m[3]};
        break;
      }
    }
    snapshot.push_back(std::move(value));
  }
  return snapshot;
}

std::vector<std::string> gl_state_changes(const GlStateSnapshot& before, const GlStateSnapshot& after) {
  std::vector<std::string> changes;
  for (size_t i = 0; i < before.size() && i < after.size() && i < std::size(kEntries); ++i) {
    if (before[i].values == after[i].values) continue;
    const Entry& entry = kEntries[i];
    changes.push_back(std::string(entry.name) + " " + values_text(entry, after[i].values) + " (was " +
                      values_text(entry, before[i].values) + ")");
  }
  return changes;
}

std::vector<std::string> protected_gl_state_names() {
  std::vector<std::string> names;
  for (const Entry& entry : kEntries) names.emplace_back(entry.name);
  return names;
}

}  // namespace pfx::validate
