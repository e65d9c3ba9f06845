#include "filter_gl.hpp"

#include <cstdio>

#include "adapter_plugins.hpp"

namespace pfx::gst {
namespace {

// Plugin messages reach GStreamer's log through stderr, above INFO: inside somebody else's
// pipeline only what a user must act on is said.
void log_to_stderr(pfx_log_level level, const std::string& source, const std::string& message) {
  if (level < PFX_LOG_WARNING) return;
  std::fprintf(stderr, "pfxfilter: %s: [%s] %s\n", host::log_level_name(level), source.c_str(), message.c_str());
}

}  // namespace

std::unique_ptr<FilterGl> FilterGl::start(host::GlProcLoader loader, const std::string& library,
                                          std::vector<std::string>* messages, std::string* error) {
  if (!adapters::load_host_gl(loader, error)) return nullptr;
  std::unique_ptr<FilterGl> self(new FilterGl);
  self->registry_ = std::make_shared<host::PluginRegistry>(loader, log_to_stderr, "pfxfilter (GStreamer)");
  *messages = adapters::load_adapter_plugins(*self->registry_, {library, {PFX_GST_TO_PLUGINS, "../../plugins"}});
  self->filter_ = adapters::TextureFilter::create(self->registry_, error);
  if (!self->filter_) return nullptr;
  return self;
}

FilterGl::~FilterGl() {
  filter_.reset();  // before the registry whose plugins it runs
}

bool FilterGl::runs_passes(const adapters::ChainSettings& settings, uint64_t revision, int width, int height,
                           double time_seconds, std::string* warning) {
  return filter_->runs_passes(settings, revision, width, height, time_seconds, warning);
}

bool FilterGl::process(const adapters::ChainSettings& settings, uint64_t revision, uint32_t in, uint32_t out,
                       int width, int height, double time_seconds, std::string* warning, std::string* error) {
  return filter_->process(settings, revision, in, out, width, height, time_seconds, warning, error);
}

}  // namespace pfx::gst
