#include "frame_ends.hpp"

namespace pfx::host {
namespace {

GLint internal_format(GLuint texture) {
  GLint format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return format;
}

// A GL_RGBA8 view of an sRGB texture: its codes as stored. 0 where none can be made (a texture
// whose storage is not immutable, or not 2D); the chain then copies. The GL's errors are the
// chain's to read here: execute cleared the embedding program's before the frame.
GLuint raw_view(GLuint texture) {
  GLint immutable = GL_FALSE;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  if (!immutable) return 0;
  GLuint view = 0;
  glGenTextures(1, &view);  // a view takes a name that is not yet a texture
  glTextureView(view, GL_TEXTURE_2D, texture, GL_RGBA8, 0, 1, 0, 1);
  if (glGetError() == GL_NO_ERROR) return view;
  glDeleteTextures(1, &view);
  return 0;
}

void choose_color(const Declaration& first, FrameConversion& conversion, FrameResources* r) {
  const GLuint color = r->textures.color;
  r->color_bound = color;
  if (!first.display_referred()) {
    if (!first.samples_and_draws() && is_eight_bit_texture(color)) r->color_step = ColorStep::WIDEN;
    return;
  }
  if (internal_format(color) == GL_SRGB8_ALPHA8 && samples_as_stored(color)) {
    r->color_view = raw_view(color);
    r->color_bound = r->color_view;
    if (r->color_view) return;
    r->color_step = ColorStep::COPY_CODES;
  } else {
    r->color_step = ColorStep::ENCODE;  // linear light, or codes behind a swizzle only sampling applies
  }
  r->color_bound = conversion.codes_color(r->frame.width, r->frame.height);
}

// The last effect writes the chain's own texture: RGBA16F for a linear effect, codes for a
// display-referred one.
void write_chain_copy(OutputStep step, FrameConversion& conversion, FrameResources* r) {
  const bool codes = step != OutputStep::NARROW;
  r->output_step = step;
  r->output_bound = codes ? conversion.codes_output(r->frame.width, r->frame.height)
                          : conversion.wide_output(r->frame.width, r->frame.height);
  r->output_to_framebuffer = false;
  r->output_eight_bit = codes;
  r->output_srgb_writes = false;
}

void choose_output(const Declaration& last, bool reads_output, FrameConversion& conversion, FrameResources* r) {
  const HostOutput& output = r->output;
  r->output_bound = output.texture;
  r->output_to_framebuffer = output.to_framebuffer;
  r->output_eight_bit = output.to_framebuffer || is_eight_bit_texture(output.texture);
  // Drawing into an sRGB texture encodes (a plain RGBA8 one ignores the switch); a framebuffer
  // says which it holds.
  r->output_srgb_writes = output.to_framebuffer ? output.srgb : r->output_eight_bit;
  if (!last.display_referred()) {
    // A framebuffer cannot be sampled: a last effect that reads its "output" back writes the copy.
    if (r->output_eight_bit && (!last.samples_and_draws() || (output.to_framebuffer && reads_output)))
      write_chain_copy(OutputStep::NARROW, conversion, r);
    return;
  }
  const bool srgb_codes = output.to_framebuffer ? output.srgb : internal_format(output.texture) == GL_SRGB8_ALPHA8;
  if (!srgb_codes) return write_chain_copy(OutputStep::DECODE, conversion, r);
  if (output.to_framebuffer && !reads_output) {
    r->output_srgb_writes = false;  // codes go in as they are
    return;
  }
  if (!output.to_framebuffer) r->output_view = raw_view(output.texture);
  if (!r->output_view) return write_chain_copy(OutputStep::COPY_CODES, conversion, r);
  r->output_bound = r->output_view;
  r->output_srgb_writes = false;
}

}  // namespace

void choose_frame_ends(const Declaration& first, const Declaration& last, bool reads_output,
                       FrameConversion& conversion, FrameResources* resources) {
  choose_color(first, conversion, resources);
  choose_output(last, reads_output, conversion, resources);
}

void release_frame_views(FrameResources* resources) {
  for (GLuint* view : {&resources->color_view, &resources->output_view})
    if (*view) {
      glDeleteTextures(1, view);
      *view = 0;
    }
}

bool run_color_step(FrameResources& r, FrameConversion& conversion, std::string* name, std::string* error) {
  const uint32_t width = r.frame.width, height = r.frame.height;
  const GLuint color = r.textures.color;
  switch (r.color_step) {
    case ColorStep::AS_IS: *name = ""; return true;
    case ColorStep::WIDEN:
      *name = "8-bit colour to RGBA16F";
      return conversion.widen_color(color, width, height, &r.color_bound, error);
    case ColorStep::COPY_CODES:
      *name = "8-bit colour copied as codes";
      glCopyImageSubData(color, GL_TEXTURE_2D, 0, 0, 0, 0, r.color_bound, GL_TEXTURE_2D, 0, 0, 0, 0,
                         static_cast<GLsizei>(width), static_cast<GLsizei>(height), 1);
      return true;
    case ColorStep::ENCODE:
      *name = "colour to sRGB codes";
      return conversion.draw_copy(color, r.color_bound, width, height, error, Transfer::ENCODE);
  }
  return false;
}

bool run_output_step(const FrameResources& r, GlPool& pool, FrameConversion& conversion, std::string* name,
                     std::string* error) {
  const uint32_t width = r.frame.width, height = r.frame.height;
  const HostOutput& output = r.output;
  const auto w = static_cast<GLsizei>(width), h = static_cast<GLsizei>(height);
  switch (r.output_step) {
    case OutputStep::AS_IS: *name = ""; return true;
    case OutputStep::NARROW:
    case OutputStep::DECODE: {
      const Transfer transfer = r.output_step == OutputStep::DECODE ? Transfer::DECODE : Transfer::COPY;
      *name = r.output_step == OutputStep::DECODE ? "sRGB codes to output" : "RGBA16F to 8-bit output";
      return output.to_framebuffer
                 ? conversion.draw_into(r.output_bound, output.framebuffer, output.srgb, width, height, error, transfer)
                 : conversion.draw_copy(r.output_bound, output.texture, width, height, error, transfer);
    }
    case OutputStep::COPY_CODES:
      *name = "sRGB codes copied to output";
      if (!output.to_framebuffer) {
        glCopyImageSubData(r.output_bound, GL_TEXTURE_2D, 0, 0, 0, 0, output.texture, GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
        return true;
      }
      // GL_FRAMEBUFFER_SRGB is off (the pass state): a blit moves the codes as they are.
      glBindFramebuffer(GL_READ_FRAMEBUFFER, pool.framebuffer_for(r.output_bound));
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, output.framebuffer);
      glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      return true;
  }
  return false;
}

}  // namespace pfx::host
