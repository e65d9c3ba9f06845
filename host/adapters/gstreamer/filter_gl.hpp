// What pfxfilter does on GStreamer's GL thread, apart from GStreamer's types: the plugins and
// the chain, run from the input texture to the output texture on GStreamer's own context
// (texture_filter.hpp: no copy through the CPU, GL state put back).
//
// No GL header here: the element's file includes GStreamer's, which cannot meet glad's.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "chain_settings.hpp"
#include "texture_filter.hpp"

namespace pfx::gst {

class FilterGl {
 public:
  // With the context current (desktop OpenGL 4.5, checked by the caller): loads GL through
  // `loader` and the pfx plugins. Null with *error. *messages gets the plugins refused.
  static std::unique_ptr<FilterGl> start(host::GlProcLoader loader, const std::string& library,
                                         std::vector<std::string>* messages, std::string* error);
  ~FilterGl();

  // Whether a frame of that size would run any pass (TextureFilter::runs_passes): when not, the
  // element hands the buffer on as it came.
  bool runs_passes(const adapters::ChainSettings& settings, uint64_t revision, int width, int height,
                   double time_seconds, std::string* warning);

  // Runs the chain the settings name over `in` into `out` (textures of width x height, RGBA8 or
  // RGB10_A2, row 0 at the top). Settings that do not build (an unknown effect, a bad
  // assignment, a missing preset) copy the frame unchanged and put the reason in *warning, once
  // per revision of the settings. False with *error only when GL itself failed.
  bool process(const adapters::ChainSettings& settings, uint64_t revision, uint32_t in, uint32_t out, int width,
               int height, double time_seconds, std::string* warning, std::string* error);

 private:
  FilterGl() = default;
  std::shared_ptr<host::PluginRegistry> registry_;
  std::unique_ptr<adapters::TextureFilter> filter_;
};

}  // namespace pfx::gst
