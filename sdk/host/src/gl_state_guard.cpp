#include "pfx/host/gl_state_guard.hpp"

#include "gl_state_scope.hpp"

namespace pfx::host {

GlStateGuard::GlStateGuard(const Chain& chain) : chain_(chain) {
  if (const GlLimits* limits = chain.gl_limits()) scope_ = std::make_unique<GlStateScope>(*limits);
  ++chain_.guards_;
}

GlStateGuard::~GlStateGuard() {
  --chain_.guards_;
  scope_.reset();
}

}  // namespace pfx::host
