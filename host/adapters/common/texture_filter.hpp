// A chain run from one texture to another on a host's own GL context (GStreamer's GL thread,
// OBS's graphics thread), with no copy through the CPU: the 8-bit frame is decoded, run through
// the chain the settings name, and encoded back; a frame no pass would change is not touched at
// all (runs_passes: the host hands its own on). GL state the host set is put back (libpfxhost's
// GlStateGuard), so what the host draws next sees what it would without pfx.
//
// No GL header here: hosts include their own (GStreamer's, OBS's), which cannot meet glad's.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "chain_settings.hpp"

namespace pfx::adapters {

// With the host's context current: loads the GL functions pfx calls through `loader`. False with
// *error when the context is not desktop OpenGL 4.5.
bool load_host_gl(host::GlProcLoader loader, std::string* error);

class TextureFilter {
 public:
  // With the context current and GL loaded (load_host_gl): the textures and programs the frames
  // need. The registry is shared: several filters may run its effects. Null with *error.
  static std::unique_ptr<TextureFilter> create(std::shared_ptr<const host::PluginRegistry> registry,
                                               std::string* error);
  ~TextureFilter();  // with the context current: its GL objects go, the host's state is put back

  // Applies the settings as process() does and tells whether a frame of that size would run any
  // pass: false when no effect is on, every effect on is a no-op with its values, or the settings
  // do not build (*warning then says why, once per revision). The host then hands its frame on as
  // it came instead of calling process(): nothing is decoded, copied or encoded.
  bool runs_passes(const ChainSettings& settings, uint64_t revision, int width, int height, double time_seconds,
                   std::string* warning);

  // Runs the chain the settings name over `in` into `out` (textures of width x height, RGBA8 or
  // RGB10_A2, row 0 at the top). Settings that do not build (an unknown effect, a bad
  // assignment, a missing preset) copy the frame unchanged and put the reason in *warning, once
  // per revision of the settings. False with *error only when GL itself failed.
  bool process(const ChainSettings& settings, uint64_t revision, uint32_t in, uint32_t out, int width, int height,
               double time_seconds, std::string* warning, std::string* error);
  // Whether the last settings built a chain (false: frames pass through).
  bool runs_chain() const;

 private:
  struct Impl;
  TextureFilter();
  std::unique_ptr<Impl> impl_;
};

}  // namespace pfx::adapters
