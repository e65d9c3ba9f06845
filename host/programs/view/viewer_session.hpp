// Everything the viewer shows and changes, without the window: plugins, parameters, the chain,
// the frame source and camera, display settings, hot reload, presets, screenshots and the
// messages shown to the user. The panels and the main loop work through it. GL thread only.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>

#include <pfx/host/chain.hpp>
#include <pfx/host/plugin_watcher.hpp>

#include "file_watch.hpp"
#include "frame_source.hpp"
#include "preset.hpp"
#include "tonemap.hpp"
#include "view_options.hpp"
#include "view_output.hpp"

namespace pfx::app {

struct Message {
  bool error = false;
  std::string text;
};

class ViewerSession {
 public:
  // Loads the plugins, builds the input, the chain (preset, then --chain / --set / --camera on
  // top) and the output. With --attach there is no input: the chain and values come from the
  // attached preset, at the display-referred defaults, and source() must not be used. Null with
  // *error and *exit_code (exit_codes.hpp: usage, bad input file, effect error, internal for GL)
  // on failure.
  static std::unique_ptr<ViewerSession> create(const ViewOptions& options, const std::string& renderer,
                                               pfx::host::GlProcLoader gl_loader, std::string* error,
                                               int* exit_code);
  ~ViewerSession();
  ViewerSession(const ViewerSession&) = delete;
  ViewerSession& operator=(const ViewerSession&) = delete;

  pfx::host::PluginRegistry& registry() { return *registry_; }
  pfx::host::ParamStore& params() { return params_; }
  pfx::host::Chain& chain() { return *chain_; }
  FrameSource& source() { return *source_; }
  ToneMapSettings& tone() { return tone_; }
  const std::string& renderer() const { return renderer_; }

  // A number that changes whenever what the chain would output changes (chain order and flags,
  // parameter values, camera, frame size): the main loop renders again only when it moves.
  uint64_t state_stamp(int width, int height) const;
  // Renders the inputs and runs the chain. On failure the error is kept (render_error()) and
  // shown, and the last good output stays on screen.
  bool render(int width, int height, double time_seconds, bool force_scene);
  // The frame on screen: linear light, or for an 8-bit picture its codes (output().codes()).
  const ViewOutput& output() const { return *output_; }
  int output_width() const { return output_->width(); }
  int output_height() const { return output_->height(); }
  const std::string& render_error() const { return render_error_; }
  double last_render_ms() const { return last_render_ms_; }

  // --edit: the assignments due at this frame (1 for the first), made as their widgets make them.
  void apply_edits(const std::vector<ViewOptions::Edit>& edits, long long frame);

  // Hot reload: polls the plugin files and reloads those rebuilt (keeping parameter values); the
  // files the chain's effects were made from (FX files): an edit of one changes state_stamp for
  // two frames a poll apart, so the effect runs and picks it up in any drawing mode; and the
  // preset it started from, which is applied again when another program saved it.
  bool watching() const { return watching_; }
  void set_watching(bool on);
  void poll_plugins(double now_seconds);
  uint64_t reload_count() const { return reload_count_; }

  // Presets: the current look, and applying one read from `path` (the chain, values, camera,
  // display). What of it is not loaded or does not fit is left out and named in *left_out
  // (chain_builder.hpp).
  Preset current_preset() const;
  bool apply_preset(const Preset& preset, const std::string& path, std::string* error, std::string* left_out);
  std::string& preset_path() { return preset_path_; }
  void save_preset();  // to preset_path(), reported as a message
  void load_preset() { load_preset(preset_path_); }
  void load_preset(const std::string& path);  // applied and reported, or its error shown

  // Screenshots: the current output as pfx-render writes it.
  bool write_frame(const std::string& png_path, std::string* error);
  // F12: DIR/pfx-view-NNNN.png, .exr and the preset as .json; reported as a message.
  void take_screenshot();

  void info(const std::string& text);     // stdout "pfx-view: ..."
  void warning(const std::string& text);  // stderr "pfx-view: warning: ...", shown in red
  void error(const std::string& text);    // stderr "pfx-view: error: ...", shown in red
  const std::deque<Message>& messages() const { return messages_; }

 private:
  ViewerSession() = default;
  bool build_chain(const std::vector<PresetEffect>& effects, std::string* error);
  void remember(Message message);
  void log_plan_and_reports();
  // The files the chain's effects were made from (an FX effect's .fx), for sources_.
  std::vector<std::string> chain_source_files() const;

  std::string renderer_;
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  pfx::host::ParamStore params_;
  std::unique_ptr<pfx::host::Chain> chain_;
  std::unique_ptr<FrameSource> source_;
  ToneMapSettings tone_;
  pfx::host::PluginWatcher watcher_;
  bool watching_ = false;
  double last_poll_ = -1;
  uint64_t reload_count_ = 0;
  // Edits of the chain's source files: each adds frames to draw (state_stamp changes).
  FileWatch sources_;
  double last_source_look_ = -1;
  uint64_t source_frames_ = 0;
  int source_frames_owed_ = 0;
  // The preset the viewer started from (--preset), applied again when it is saved by another
  // program (an editor); "" for none.
  std::string watched_preset_;
  FileWatch preset_watch_;
  std::unique_ptr<ViewOutput> output_ = std::make_unique<ViewOutput>();
  uint64_t frame_index_ = 0;
  bool verbose_ = false;
  std::string logged_passes_;
  std::map<std::string, std::string> logged_reports_;
  std::string render_error_;
  double last_render_ms_ = 0;
  std::string preset_path_, shots_dir_;
  std::deque<Message> messages_;
};

}  // namespace pfx::app
