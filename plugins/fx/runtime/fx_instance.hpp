#pragma once
// An instance of an FX technique. Its passes, as pfx sees them:
//   encode   the frame's linear colour -> the 8-bit, sRGB-encoded back buffer FX shaders expect
//   pass i   each pass of the technique, on the effect's own textures (kept from frame to frame,
//            as FX effects expect) or the back buffer
//   decode   the back buffer -> the effect's output, linear again
// A host of ABI 1.6 or later hands the effect sRGB codes and takes them back
// (PFX_DECLARATION_DISPLAY_REFERRED), and the chain converts only where a neighbour wants linear
// light. Then nothing is encoded or decoded (fx_pass_layout.hpp): the first pass ("begin") only
// gets the technique ready, its passes sample the host's colour as the back buffer until one
// writes the back buffer, and the last of those draws into the output with the frame's alpha. A
// technique that cannot has "copy in" first or "finish" last, which only move the picture.
// The FX source is compiled again when the frame size changes (BUFFER_WIDTH and its kin are
// constants of the source), when the file or one of its includes is edited and when the host sets
// other preprocessor definitions, on the CPU in declare and into GL programs in the next run.
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glad/gl.h>
#include <pfx/effect.h>

#include "codegen/uniform_block.hpp"
#include "effect_compiler.hpp"
#include "fx_catalog.hpp"
#include "fx_definitions.hpp"
#include "fx_frame_params.hpp"
#include "fx_pass_layout.hpp"
#include "fx_gl_objects.hpp"
#include "fx_programs.hpp"
#include "fx_source_watch.hpp"
#include "fx_stencil.hpp"
#include "fx_uniform_values.hpp"

namespace pfx_fx {

class FxInstance {
 public:
  FxInstance(const FxEffectEntry& entry, const pfx_host* host) : entry_(entry), host_(host) {}
  ~FxInstance();
  bool create_gl();  // the programs that do not depend on the source: encode and decode
  pfx_status declare(const pfx_frame* frame, const pfx_value* params, pfx_declaration* out);
  pfx_status run_pass(const pfx_pass_context* context);
  // "compile_ms" (the FX source to GLSL, on the CPU), "gl_build_ms" (the GL programs) and
  // "programs_from_cache" of the last compile, for pfx-fx-check and the frame reports.
  const char* report_json();
  // The host's preprocessor definitions (fx_definitions.hpp), compiled with from the next frame on,
  // as an edit is. PFX_INVALID_ARGUMENT for a malformed list, which changes nothing.
  pfx_status set_definitions(const char* list);

 private:
  // The source compiled for a frame size and checked to hold the technique, or null with *error.
  std::unique_ptr<pfx::fx::CompiledEffect> compile_at(int width, int height, std::string* error);
  void adopt(std::unique_ptr<pfx::fx::CompiledEffect> compiled);  // its passes, for the next run
  bool compile_source(int width, int height);  // CPU
  void note_ignored_features();  // once: what of the file pfx does not honour (#pragma reshade)
  // Edits (watch_): an edit that compiles replaces the running version (parameter values kept:
  // the host owns them), one that does not is logged and the last version that compiled keeps
  // running.
  void reload_if_edited();
  // The descriptors of passes_ for layout_ and the compiled technique.
  void declare_passes();
  bool build_gl();  // GL textures and samplers, for the compiled source (programs_ builds the programs)
  void release_gl();
  void log(pfx_log_level level, const std::string& message) const;
  // Attaches `textures` as colour attachments 0..count-1 of the effect's framebuffer (the rest
  // detached), binds it for drawing and reading, and sets the viewport.
  void draw_into(const GLuint* textures, int count, int width, int height);
  void run_encode(const pfx_pass_context& context);
  void convert_depth(const pfx_pass_context& context);
  void run_decode(const pfx_pass_context& context);
  void run_fx_pass(int index, const pfx_pass_context& context);
  // The technique's output pass (layout_.output_pass), drawn into the host's output.
  void draw_output(const pfx::fx::PassInfo& pass, const pfx::fx::GeneratedPass& g, const PassProgram& p,
                   const pfx_pass_context& context);
  void bind_resources(const pfx::fx::GeneratedPass& generated, const PassProgram& program, int target_height);
  // This frame's uniform values into the uniform buffer, when they differ from what it holds.
  void upload_uniforms();
  GLuint texture_for_sampler(const pfx::fx::SamplerInfo& sampler) const;
  const pfx::fx::TechniqueInfo& technique() const;

  const FxEffectEntry& entry_;
  const pfx_host* host_;
  Definitions definitions_;  // the host's, without the names pfx defines itself
  bool redefined_ = false;   // set since the last compile

  // CPU side, for the compiled size.
  std::unique_ptr<pfx::fx::CompiledEffect> compiled_;
  int compiled_width_ = 0, compiled_height_ = 0;
  bool needs_depth_ = false;
  std::vector<pfx_pass_desc> passes_;
  std::vector<std::string> pass_names_;
  pfx_pass_input color_input_[2]{};
  UniformValues uniforms_;
  FrameParams frame_params_;  // the values of parameters that follow the frame size

  // GL side.
  bool gl_current_ = false;  // built for compiled_
  GLuint encode_program_ = 0, decode_program_ = 0, depth_program_ = 0, framebuffer_ = 0;
  FxPrograms programs_;  // the technique's passes, live or with the uniforms as constants
  std::vector<GlTexture> textures_;  // per model texture (unused for the back buffer and depth)
  std::vector<GLuint> samplers_;
  GlTexture back_buffer_[2];
  FxStencil stencil_;  // when a pass enables the stencil test
  // The effect's uniform block (every pass of every program reads it): one buffer, written when a
  // value changes, so a value is converted once per change, not once per pass or program.
  pfx::fx::UniformBlockLayout block_layout_;
  GLuint uniform_buffer_ = 0;  // 0: the effect has no uniforms
  std::vector<unsigned char> block_bytes_, uploaded_block_;
  int current_ = 0;  // which back buffer holds the picture
  // The host's colour, while the picture is still there (samples_frame_): passes sample it as the
  // back buffer until one writes the back buffer; 0 from then on.
  GLuint frame_color_ = 0;
  GLuint frame_color_srgb_ = 0;  // an sRGB view of it, for layout_.srgb_frame_view
  void leave_frame();            // the frame is no longer sampled: forget it, delete the view
  bool display_referred_ = false;  // the host (ABI 1.6+) hands and takes sRGB codes
  FxPassLayout layout_;            // how the technique's passes are declared
  // FX's depth buffer: the frame's depth as standard window depth of a projection with its far
  // plane 1000 near planes away (what ReShade.fxh's GetLinearizedDepth reads with the settings
  // compile_options defines), made by depth_program_ from any pfx depth encoding. Without depth
  // in the frame it is one texel at the far plane.
  GlTexture fx_depth_;
  bool depth_in_frame_ = false;
  bool told_no_depth_ = false;
  bool told_ignored_ = false;
  double compile_ms_ = 0, gl_build_ms_ = 0;
  SourceWatch watch_;
  std::unique_ptr<pfx::fx::CompiledEffect> pending_;  // an edit with another pass count, for the next declare
  std::string report_;
};

}  // namespace pfx_fx
