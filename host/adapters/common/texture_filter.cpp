#include "texture_filter.hpp"

#include <glad/gl.h>
#include <pfx/host/gl_state_guard.hpp>

#include "display_frame.hpp"
#include "frame_chain.hpp"

namespace pfx::adapters {

struct TextureFilter::Impl {
  std::shared_ptr<const host::PluginRegistry> registry;
  std::unique_ptr<gl::DisplayFrame> frame;
  std::unique_ptr<FrameChain> chain;  // null while the settings do not build
  std::unique_ptr<FrameChain> empty;  // no effect: what the state guard is made from
  app::Transfer transfer = app::Transfer::SRGB;
  uint64_t applied = 0;
  uint64_t frames = 0;
  // Builds the chain when the settings changed since the last call; *warning says why it did not.
  void apply(const ChainSettings& settings, uint64_t revision, std::string* warning);
};

namespace {

GLADapiproc load_through(void* user, const char* name) {
  return reinterpret_cast<GLADapiproc>((*static_cast<const host::GlProcLoader*>(user))(name));
}

}  // namespace

bool load_host_gl(host::GlProcLoader loader, std::string* error) {
  if (!gladLoadGLUserPtr(load_through, &loader) || !GLAD_GL_VERSION_4_5) {
    *error = "the host's context has no OpenGL 4.5 functions";
    return false;
  }
  return true;
}

std::unique_ptr<TextureFilter> TextureFilter::create(std::shared_ptr<const host::PluginRegistry> registry,
                                                     std::string* error) {
  std::unique_ptr<TextureFilter> self(new TextureFilter);
  Impl& impl = *self->impl_;
  impl.registry = std::move(registry);
  std::vector<std::string> notes;
  impl.empty = FrameChain::build(*impl.registry, {}, "set", &notes, error);
  if (!impl.empty) return nullptr;
  host::GlStateGuard guard(impl.empty->chain());
  impl.frame = std::make_unique<gl::DisplayFrame>();
  if (!impl.frame->create(error)) return nullptr;
  return self;
}

TextureFilter::TextureFilter() : impl_(std::make_unique<Impl>()) {}

TextureFilter::~TextureFilter() {
  if (!impl_->empty) return;
  // The chain's and the frame's GL objects go on the host's context, whose state is put back
  // afterwards.
  {
    host::GlStateGuard guard(impl_->empty->chain());
    impl_->chain.reset();
    impl_->frame.reset();
  }
  impl_->empty.reset();  // before the registry whose plugins it was made with
}

bool TextureFilter::runs_chain() const { return impl_->chain != nullptr; }

void TextureFilter::Impl::apply(const ChainSettings& settings, uint64_t revision, std::string* warning) {
  if (revision == applied) return;
  applied = revision;
  chain.reset();
  app::ChainRecipe recipe;
  std::vector<std::string> notes;
  std::string why;
  if (resolve_chain_settings(settings, *registry, &transfer, &recipe, &why)) {
    if (!recipe.left_out.empty()) notes.push_back(recipe.left_out);
    chain = FrameChain::build(*registry, recipe, "set", &notes, &why);
  }
  if (!chain) *warning = why + "; frames pass through unchanged";
  for (const auto& note : notes) *warning += (warning->empty() ? "" : "; ") + note;
}

bool TextureFilter::runs_passes(const ChainSettings& settings, uint64_t revision, int width, int height,
                                double time_seconds, std::string* warning) {
  Impl& impl = *impl_;
  if (revision != impl.applied) {
    // Building the chain creates its effects on the host's context; the host's state is put back.
    // Declaring needs no GL, so a frame with settings as before saves no state at all (on a driver
    // that runs GL on a thread of its own, every query of state waits for that thread).
    host::GlStateGuard guard(impl.empty->chain());
    impl.apply(settings, revision, warning);
  }
  if (!impl.chain) return false;
  bool passes = false;
  std::string why;
  if (!impl.chain->plans_passes(width, height, time_seconds, impl.frames + 1, &passes, &why)) {
    *warning = why + "; frames pass through unchanged";
    impl.chain.reset();
    return false;
  }
  return passes;
}

bool TextureFilter::process(const ChainSettings& settings, uint64_t revision, uint32_t in, uint32_t out, int width,
                            int height, double time_seconds, std::string* warning, std::string* error) {
  Impl& impl = *impl_;
  host::GlStateGuard guard(impl.empty->chain());
  impl.apply(settings, revision, warning);
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
  return no_gl_error(error);
}

}  // namespace pfx::adapters
