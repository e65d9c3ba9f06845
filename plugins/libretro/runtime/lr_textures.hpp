#pragma once
// The GL textures a chain draws into and samples, all stored with their top row first (row 0 is the
// picture's top, as in Vulkan, where slang shaders were written: a shader's TexCoord.y and
// gl_FragCoord.y grow downwards in every pass but the last, which draws into the host's frame and
// reads gl_FragCoord with an upper-left origin):
//   - the original picture of this frame and of the `history` frames before it, a ring turned at
//     every frame (OriginalHistoryN; cleared to transparent black until filled);
//   - each pass's output, two of them for a pass whose feedback is read (the one drawn last frame
//     is PassFeedbackN), none for the last pass when it draws straight into the output;
//   - the preset's lookup textures, 8-bit, never sRGB;
//   - a sampler object per filter, wrap mode and mipmap use.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <glad/gl.h>

#include "chain_plan.hpp"
#include "preset.hpp"

namespace pfx_libretro {

class LrTextures {
 public:
  LrTextures() = default;
  LrTextures(const LrTextures&) = delete;
  LrTextures& operator=(const LrTextures&) = delete;
  ~LrTextures() { release(); }

  // The preset's lookup textures, decoded (no GL). False with the file and why in *error.
  bool load_lookups(const pfx::libretro::Preset& preset, std::string* error);
  // Uploads what load_lookups decoded, once: in a pass, where the ABI sets the pixel store
  // (create runs under whatever state the host's engine left).
  void upload_lookups();
  // Makes the frame textures for a picture of `content` and passes of `sizes` (history and
  // feedback start black again).
  void make(const pfx::libretro::ChainPlan& plan, pfx::libretro::PixelSize content,
            const std::vector<pfx::libretro::PixelSize>& sizes);
  // At the start of a frame: the history ring and the feedback pairs turn.
  void advance();
  void release();

  GLuint original(int frames_back = 0) const;  // frames_back <= history
  GLuint pass_output(int pass) const;          // this frame's (0 for a pass drawing into the output)
  GLuint pass_feedback(int pass) const;        // the last frame's; this frame's for a pass without feedback
  GLuint lookup(int index) const { return lookups_[static_cast<std::size_t>(index)].texture; }
  pfx::libretro::PixelSize lookup_size(int index) const { return lookups_[static_cast<std::size_t>(index)].size; }
  int pass_levels(int pass) const { return passes_[static_cast<std::size_t>(pass)].levels; }
  int original_levels() const { return original_levels_; }
  bool made() const { return made_; }
  // The bytes the frame and lookup textures hold (every mip level), for the effect's report.
  std::size_t bytes() const { return frame_bytes_ + lookup_bytes_; }

  // A sampler object (made once) that filters linearly or not, wraps so, and uses mips or not.
  GLuint sampler(bool linear, pfx::libretro::WrapMode wrap, bool mipmaps);

 private:
  struct PassTextures {
    GLuint texture[2] = {0, 0};
    int levels = 1;
  };
  struct Lookup {
    GLuint texture = 0;
    pfx::libretro::PixelSize size;
    bool mipmap = false;
    std::vector<unsigned char> rgba;  // until uploaded
  };
  std::vector<GLuint> history_;  // ring: history_[current_] is this frame's
  int original_levels_ = 1;
  std::size_t current_ = 0;
  std::vector<PassTextures> passes_;
  int parity_ = 0;  // which of a feedback pair is drawn this frame
  std::vector<Lookup> lookups_;
  std::map<std::tuple<bool, int, bool>, GLuint> samplers_;
  bool made_ = false;
  std::size_t frame_bytes_ = 0, lookup_bytes_ = 0;
  void release_frame_textures();
};

// The GL internal format of a `#pragma format` name (GL_RGBA8 for an unknown one).
GLenum gl_format(const std::string& format);
// Mip levels of a full chain for a texture of `size`.
int full_mip_levels(pfx::libretro::PixelSize size);
// Bytes of a texture of `size` with `levels` mips, in a `#pragma format`.
std::size_t texture_bytes(const std::string& format, pfx::libretro::PixelSize size, int levels);

}  // namespace pfx_libretro
