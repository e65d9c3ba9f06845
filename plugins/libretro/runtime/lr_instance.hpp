#pragma once
// An instance of a libretro preset. Its passes, as pfx sees them:
//   content   the host's frame -> the original picture (Original): turned top row first, and
//             averaged down to the content size when the effect's content options ask for one;
//             this frame's place in the history ring
//   pass i    each pass of the preset, into its own texture (lr_textures.hpp), the last one
//             straight into the host's output
//   finish    only when the last pass renders into a texture of its own (it has a scale type, or
//             its feedback is read): that texture stretched over the output, linearly filtered
// The effect works on display-referred values, the sRGB codes of an 8-bit frame, as the shaders
// were written for (PFX_DECLARATION_DISPLAY_REFERRED; a host older than ABI 1.6 is refused): the
// host converts only where a neighbour wants linear light.
#include <chrono>
#include <string>
#include <vector>

#include <glad/gl.h>
#include <pfx/effect.h>

#include "chain_plan.hpp"
#include "lr_catalog.hpp"
#include "lr_passes.hpp"
#include "lr_textures.hpp"
#include "lr_uniform_values.hpp"

namespace pfx_libretro {

class LrInstance {
 public:
  LrInstance(const LrEffectEntry& entry, const pfx_host* host) : entry_(entry), host_(host) {}
  ~LrInstance();
  // Compiles the passes and loads the lookup textures; PFX_OK, or an error logged.
  pfx_status create();
  pfx_status declare(const pfx_frame* frame, const pfx_value* params, pfx_declaration* out);
  pfx_status run_pass(const pfx_pass_context* context);
  // "passes", "compile_ms" (the shaders to GLSL, on the CPU), "gl_build_ms" (the GL programs) and
  // "texture_bytes" (what the chain's own textures hold: the host's peak target bytes leave them out).
  const char* report_json();

 private:
  void log(pfx_log_level level, const std::string& message) const;
  void run_content(const pfx_pass_context& context);
  void run_preset_pass(int index);
  // Writes the block's values for this frame and uploads them where they changed.
  void update_block(const pfx::libretro::ReflectedBlock& block, const PassValues& values, GLuint buffer,
                    std::vector<unsigned char>& uploaded);
  void run_finish(const pfx_pass_context& context);
  // Binds what pass `index` samples to the units its shader names.
  void bind_samplers(int index);
  GLuint sampler_for(int settings_pass, bool integer);
  void draw_into(GLuint texture, pfx::libretro::PixelSize size, bool srgb);

  const LrEffectEntry& entry_;
  const pfx_host* host_;
  std::vector<LrPass> passes_;
  pfx::libretro::ChainPlan plan_;

  // Declared for the coming frames.
  pfx::libretro::PixelSize viewport_, content_;
  std::vector<pfx::libretro::PixelSize> sizes_, lookup_sizes_;
  std::vector<double> values_;  // per shader parameter
  std::vector<std::string> pass_names_;
  std::vector<pfx_pass_desc> pass_descs_;
  pfx_pass_input color_input_{};

  // This frame.
  std::uint32_t frame_count_ = 0;
  std::uint32_t frame_time_delta_us_ = 16667;
  float fps_ = 60;
  double last_time_ = -1;

  LrTextures textures_;
  bool remake_ = true;  // the frame textures do not fit the declared sizes
  GLuint vao_ = 0, vertices_ = 0, glsl_vertices_ = 0, framebuffer_ = 0, content_program_ = 0, finish_program_ = 0;
  std::vector<unsigned char> scratch_;  // a block's values being written
  std::vector<GLuint> high_units_;      // units past 15 the running pass bound, unbound when it returns
  double compile_ms_ = 0, gl_build_ms_ = 0;
  int programs_from_cache_ = 0;  // of this instance's pass programs, those the cache gave
  std::string report_;
};

}  // namespace pfx_libretro
