#pragma once
// The GL objects of one compiled FX effect: a texture (with an sRGB view where the format has
// one) per FX texture, a sampler object per FX sampler, and the mapping of FX's formats, address
// modes, filters and blend states onto GL's.
#include <string>
#include <vector>

#include <glad/gl.h>

#include "model/effect_model.hpp"

namespace pfx_fx {

struct GlFormat {
  GLenum internal;       // GL_RGBA8
  GLenum srgb_internal;  // GL_SRGB8_ALPHA8 for a view, 0 when the format has no sRGB form
};
GlFormat gl_format(pfx::fx::TextureFormat format);

struct GlTexture {
  GLuint texture = 0;
  GLuint srgb_view = 0;  // sampled by SRGBTexture samplers, written with SRGBWriteEnable
  GLenum target = GL_TEXTURE_2D;
  int width = 1, height = 1, depth = 1, levels = 1;
  GLenum internal = GL_RGBA8;
};

// Immutable storage of the texture's size, format and levels, cleared to zero (ReShade's initial
// contents). Returns false with `error` when GL refuses.
bool create_texture(const pfx::fx::TextureInfo& info, GlTexture& out, std::string& error);
// The same for a texture of a given 2D size and format (the back buffer).
bool create_texture_2d(int width, int height, GLenum internal, GLenum srgb_internal, GlTexture& out, std::string& error);
void delete_texture(GlTexture& texture);

// A sampler object with the FX sampler's states. Integer textures are read texel by texel: GL
// would call them incomplete under a linear filter, and every read would give 0.
GLuint create_sampler(const pfx::fx::SamplerInfo& info, int texture_levels, bool integer_texture);

GLenum gl_blend_op(pfx::fx::BlendOp op);
GLenum gl_blend_factor(pfx::fx::BlendFactor factor);
GLenum gl_topology(pfx::fx::Topology topology);

}  // namespace pfx_fx
