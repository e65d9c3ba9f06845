#include "pfx/host/gl_state_guard.hpp"

#include "gl_state_scope.hpp"

namespace pfx::host {

GlStateGuard::GlStateGuard(const Chain& chain) {
  if (const GlLimits* limits = chain.gl_limits()) scope_ = std::make_unique<GlStateScope>(*limits);
}

GlStateGuard::~GlStateGuard() = default;

}  // namespace pfx::host
