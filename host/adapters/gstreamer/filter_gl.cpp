#include "filter_gl.hpp"

#include <cstdio>

#include <glad/gl.h>
#include <pfx/host/gl_state_guard.hpp>

#include "adapter_plugins.hpp"
#include "display_frame.hpp"
#include "frame_chain.hpp"

namespace pfx::gst {

struct FilterGl::Impl {
  std::unique_ptr<host::PluginRegistry> registry;
  std::unique_ptr<gl::DisplayFrame> frame;
  std::unique_ptr<adapters::FrameChain> chain;  // null while the settings do not build
  std::unique_ptr<adapters::FrameChain> empty;  // no effect: what the state guard is made from
  app::Transfer transfer = app::Transfer::SRGB;
  uint64_t applied = 0;
  uint64_t frames = 0;
};

namespace {

GLADapiproc load_through(void* user, const char* name) {
  return reinterpret_cast<GLADapiproc>((*static_cast<const host::GlProcLoader*>(user))(name));
}

// Plugin messages reach GStreamer's log through stderr, above INFO: inside somebody else's
// pipeline only what a user must act on is said.
void log_to_stderr(pfx_log_level level, const std::string& source, const std::string& message) {
  if (level < PFX_LOG_WARNING) return;
  std::fprintf(stderr, "pfxfilter: %s: [%s] %s\n", host::log_level_name(level), source.c_str(), message.c_str());
}

}  // namespace

std::unique_ptr<FilterGl> FilterGl::start(host::GlProcLoader loader, const std::string& library,
                                          std::vector<std::string>* messages, std::string* error) {
  if (!gladLoadGLUserPtr(load_through, &loader) || !GLAD_GL_VERSION_4_5) {
    *error = "the context reports OpenGL 4.5 but its functions could not be loaded";
    return nullptr;
  }
  std::unique_ptr<FilterGl> self(new FilterGl);
  Impl& impl = *self->impl_;
  impl.registry = std::make_unique<host::PluginRegistry>(loader, log_to_stderr, "pfxfilter (GStreamer)");
  *messages = adapters::load_adapter_plugins(*impl.registry, {library, {PFX_GST_TO_PLUGINS, "../../plugins"}});
  std::vector<std::string> notes;
  impl.empty = adapters::FrameChain::build(*impl.registry, {}, "set", &notes, error);
  if (!impl.empty) return nullptr;
  host::GlStateGuard guard(impl.empty->chain());
  impl.frame = std::make_unique<gl::DisplayFrame>();
  if (!impl.frame->create(error)) return nullptr;
  return self;
}

FilterGl::FilterGl() : impl_(std::make_unique<Impl>()) {}

FilterGl::~FilterGl() {
  if (!impl_->empty) return;
  // The chain's, the frame's and the plugins' GL objects go on GStreamer's context, whose state
  // is put back afterwards.
  {
    host::GlStateGuard guard(impl_->empty->chain());
    impl_->chain.reset();
    impl_->frame.reset();
  }
  impl_->empty.reset();  // before the registry whose plugins it was made with
}

bool FilterGl::process(const adapters::ChainSettings& settings, uint64_t revision, uint32_t in, uint32_t out,
                       int width, int height, double time_seconds, std::string* warning, std::string* error) {
  Impl& impl = *impl_;
  host::GlStateGuard guard(impl.empty->chain());
  if (revision != impl.applied) {
    impl.applied = revision;
    impl.chain.reset();
    app::ChainRecipe recipe;
    std::vector<std::string> notes;
    std::string why;
    if (adapters::resolve_chain_settings(settings, *impl.registry, &impl.transfer, &recipe, &why))
      impl.chain = adapters::FrameChain::build(*impl.registry, recipe, "set", &notes, &why);
    if (!impl.chain) *warning = why + "; frames pass through unchanged";
    for (const auto& note : notes) *warning += (warning->empty() ? "" : "; ") + note;
  }
  // Errors left from before are not ours to report; ours are looked for at the end.
  while (glGetError() != GL_NO_ERROR) {
  }
  ++impl.frames;
  auto copy_through = [&] {
    glCopyImageSubData(in, GL_TEXTURE_2D, 0, 0, 0, 0, out, GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
  };
  if (!impl.chain) {
    copy_through();
  } else {
    impl.frame->resize(width, height);
    impl.frame->decode_texture(in, impl.transfer);
    GLuint result = 0;
    std::string why;
    if (impl.chain->render(*impl.frame, time_seconds, impl.frames, &result, &why)) {
      impl.frame->encode_texture(result, out, impl.transfer);
    } else {
      *warning = why + "; frames pass through unchanged";
      impl.chain.reset();
      copy_through();
    }
  }
  return adapters::no_gl_error(error);
}

}  // namespace pfx::gst
