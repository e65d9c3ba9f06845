// What a pfx.Chain is: a chain of effect instances with its parameter store, its plugins and a
// GL thread of its own (gl_worker.hpp) with a headless OpenGL 4.5 context, run over pictures the
// caller hands in. Plain C++ (module.cpp binds it); every failure is a python_errors.hpp
// exception carrying pfx's message.
//
// One thread at a time per chain (calls from several threads take turns on a mutex); chains on
// different threads run at the same time, each on its own context.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "camera_options.hpp"
#include "chain_builder.hpp"
#include "display_frame.hpp"
#include "display_transfer.hpp"
#include "gl_worker.hpp"
#include "image.hpp"
#include "picture_textures.hpp"

namespace pfx::python {

// Where a parameter stands until set() gives it a value. AUTO follows the picture each run is
// given, as pfx-render follows its input: the display-referred defaults for an 8-bit picture (it
// holds nothing above 1.0), the scene-referred ones for a float picture; before the first run, the
// scene-referred ones.
enum class Defaults { AUTO, SCENE, DISPLAY };

struct ChainSettings {
  // Effect ids in order; none: the preset's chain, else the default chain.
  std::optional<std::vector<std::string>> effects;
  // A pfx preset (JSON) or a ReShade preset (.ini), or "": its chain, on/off flags, values and
  // preprocessor definitions, which fix those values as set() would.
  std::string preset;
  Defaults defaults = Defaults::AUTO;
  std::string timing = "auto";  // "auto", "gpu", "finish" or "off", as pfx-render's --timing
};

// One picture through the chain.
struct RunRequest {
  app::Image image;  // the size and depth when the caller gave it (image.rgba is not read)
  bool display = false;        // the colour is `bytes`: 8-bit display-referred RGBA, row 0 at the top
  std::vector<uint8_t> bytes;  // decoded to linear light with `transfer`, the result encoded back
  // A float picture's colour, read on the GL thread straight from the caller's array (alive for
  // the call): `channels` floats a pixel (3 or 4), row 0 at the top. And where its result goes:
  // the caller's array of the same shape, written before run() returns.
  const float* colour = nullptr;
  float* result = nullptr;
  int channels = 4;
  app::Transfer transfer = app::Transfer::SRGB;
  pfx_depth_encoding depth_encoding = PFX_DEPTH_LINEAR;
  app::CameraOptions camera;
  double time_seconds = 0;
  uint64_t frame_index = 0;
};

// The chain's result for a display-referred picture: 8-bit RGBA, the picture's size (a float
// picture's result is written to RunRequest::result).
struct RunResult {
  std::vector<uint8_t> bytes;
};

class PythonChain {
 public:
  // Starts the GL thread and creates the effects (their programs compile now). What a preset names
  // that is not there (an effect, a value) is left out and described in *warnings; a preset that
  // does not read, or an effect of `effects` that is not loaded, throws.
  PythonChain(std::unique_ptr<host::PluginRegistry> registry, const ChainSettings& settings,
              std::vector<std::string>* warnings);
  ~PythonChain();
  PythonChain(const PythonChain&) = delete;
  PythonChain& operator=(const PythonChain&) = delete;

  // "bloom.threshold", "bloom#2.threshold", with a value in --set's text form. *note gets the
  // store's remark when it clamped the value.
  void set(const std::string& key, const std::string& text, std::string* note);
  // The value as the JSON listing gives it.
  nlohmann::ordered_json get(const std::string& key) const;
  // {instance: {parameter: {"value": ..., and the parameter's description}}}, in chain order.
  nlohmann::ordered_json params() const;
  // "bloom", "dof", "bloom#2": the instances in chain order.
  std::vector<std::string> instances() const;

  // Whether run() would run any pass over the request's picture, from its size, depth, camera and
  // time (its colour is not read): false when no effect is on or every one is a no-op with its
  // values, and the report then says so, as after a run. Throws what run() would for a missing
  // input. Without the GIL, like run().
  bool plans_passes(const RunRequest& request);
  // Runs the chain over the picture; the result is the picture's size. Call it without holding
  // Python's GIL: the work waits for the GL thread.
  RunResult run(const RunRequest& request);
  // The last run's report, as pfx-render's --json gives it (passes with their times, peak target
  // memory...); null before the first run.
  nlohmann::ordered_json report() const;
  const std::string& renderer() const { return renderer_; }
  // The median time of a full-frame copy pass between two RGBA16F textures of that size on the
  // chain's GL context: the unit pfx's benchmarks give costs in. Without the GIL.
  double copy_pass_ms(int width, int height);

  // Destroys the effects, their GL objects, the context and the plugins now. Later calls raise.
  void close();

 private:
  void check_open() const;
  void run_on_gl_thread(const std::function<void(std::string* error)>& job);
  void render(const RunRequest& request, RunResult* result, std::string* error);
  void hand_back(const RunRequest& request, RunResult* result);
  void report_skipped();
  bool describe(const RunRequest& request, pfx_frame* frame, std::string* error);
  bool inputs_given(const pfx_frame& frame, std::string* error);
  void follow_picture_defaults(bool display);
  app::ChainRecipe recipe_for(const ChainSettings& settings, std::vector<std::string>* warnings) const;
  void apply_preset_values(const app::ChainRecipe& recipe);
  void release_gl_objects();

  mutable std::mutex mutex_;
  Defaults defaults_ = Defaults::AUTO;
  host::DefaultSet current_defaults_ = host::DefaultSet::SCENE_REFERRED;  // what unset values are at
  std::set<std::string> set_keys_;  // "bloom#1.threshold": the values set() gave, which AUTO leaves alone
  // Kept from one run to the next while the picture's size stays (on the GL thread): the float
  // picture's textures, and the 8-bit picture's decode and encode with its textures.
  PictureTextures float_picture_;
  std::unique_ptr<gl::DisplayFrame> display_picture_;
  std::shared_ptr<adapters::GlWorker> worker_;
  std::unique_ptr<host::PluginRegistry> registry_;
  std::unique_ptr<host::ParamStore> params_;
  std::unique_ptr<host::Chain> chain_;  // made, used and destroyed on the GL thread
  std::string renderer_;
  nlohmann::ordered_json report_;
};

}  // namespace pfx::python
