// One effect of one plugin, loaded through libpfxhost into a headless GL 4.5 context, rendered
// over synthetic frames with every frame input present. Each render is checked the way a host
// relies on: the chain succeeds (no GL error, no failed pass), every pass leaves the protected GL
// state as it found it, and the output is finite wherever the input colour was.
#pragma once

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include <pfx/host/chain.hpp>

#include "child_process.hpp"
#include "gl_state.hpp"
#include "headless_context.hpp"
#include "image.hpp"

namespace pfx::validate {

class RenderRig {
 public:
  explicit RenderRig(CheckReporter& report,
                     pfx::host::DefaultSet defaults = pfx::host::DefaultSet::SCENE_REFERRED)
      : report_(report), params_(defaults) {}
  ~RenderRig();
  RenderRig(const RenderRig&) = delete;
  RenderRig& operator=(const RenderRig&) = delete;

  // Makes the context and loads the plugin (alone). False after reporting the problem.
  bool open(const std::string& plugin_path) { return open_context() && load(plugin_path); }
  // The two halves of open. `pool`: the thread pool offered to the plugin instead of the
  // registry's own.
  bool open_context();
  bool load(const std::string& plugin_path, const pfx_thread_pool* pool = nullptr);
  // Destroys the chain and the registry: the plugin's deinit, and its library closed.
  void unload();
  // Appends an instance of the effect (its create runs now). Checks create for GL errors and
  // GL state changes. False after reporting.
  bool add_effect(const std::string& effect_id);
  // Destroys the instance, checking destroy the same way.
  void remove_effect();

  // Renders `input` and checks the result; problems are reported with `label` in front. The
  // output is returned in *output when given. False when the render failed or a check did.
  bool render(const pfx::app::Image& input, const std::string& label, pfx::app::Image* output = nullptr);

  // A display frame (`codes`: 8-bit sRGB RGBA, row 0 at the top) rendered twice with the same
  // values, each by a fresh instance of the effect (the rig's one effect, made again between
  // them): handed to the chain as 8-bit textures (an sRGB view in and out, as the hosts of 8-bit
  // frames hand it), and decoded with the exact curve into RGBA16F, its result encoded back on the
  // CPU. Both results as codes (row 0 at the top); *own_passes counts the passes the chain ran
  // of its own in the 8-bit render (its conversions). False after reporting a failed render.
  bool render_display(const pfx::app::DisplayImage& codes, const std::string& label, pfx::app::DisplayImage* eight_bit,
                      pfx::app::DisplayImage* wide, int* own_passes);

  // Called right before and right after the chain renders (after the inputs are uploaded,
  // before the output is read back): to run the chain under an engine's state.
  void set_around_chain(std::function<void()> before, std::function<void()> after) {
    before_chain_ = std::move(before);
    after_chain_ = std::move(after);
  }

  pfx::host::ParamStore& params() { return params_; }
  const pfx::host::Chain& chain() const { return *chain_; }
  pfx::host::PluginRegistry* registry() { return registry_.get(); }
  const pfx_effect_desc* effect() const { return effect_; }

 private:
  // Reports a problem once per check, however many renders hit it.
  void problem_once(const std::string& text);
  // The frame render() and render_display() describe, and its textures beside the colour.
  pfx_frame describe(int width, int height) const;
  pfx::host::FrameTextures auxiliary_textures(const pfx::app::Image& input) const;
  // Runs the chain between the hooks; false after reporting.
  bool run_chain(const pfx_frame& frame, const pfx::host::FrameTextures& textures, uint32_t out, const std::string& label);
  void check_gl_calls(const std::string& what, const GlStateSnapshot& before);

  CheckReporter& report_;
  std::unique_ptr<pfx::app::HeadlessContext> context_;
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  pfx::host::ParamStore params_;
  std::unique_ptr<pfx::host::Chain> chain_;
  const pfx_effect_desc* effect_ = nullptr;
  std::vector<std::string> plugin_log_;
  GlStateSnapshot before_pass_;
  std::set<std::string> reported_;
  std::function<void()> before_chain_, after_chain_;
};

}  // namespace pfx::validate
