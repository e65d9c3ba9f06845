// For a host that draws around Chain::render in a context it does not own, such as an application
// the chain is injected into: while a guard lives, every piece of GL state render() saves, sets
// and restores (docs/sdk.md §1.5) is saved and set to the chain's starting values; the destructor
// puts the saved values back. The host's own copy passes then start from known state and leave
// the application's as they found it. On the GL thread, with the chain's context current.
//
// The state is saved once: while a guard of the chain lives, render() only sets the chain's
// starting values again (the host's passes may have moved bindings) and leaves its own state
// behind when it returns; the guard puts the engine's values back when it ends. The chain must
// outlive its guards.
#pragma once

#include <memory>

#include "pfx/host/api.hpp"
#include "pfx/host/chain.hpp"

namespace pfx::host {

class GlStateScope;

class PFX_HOST_API GlStateGuard {
 public:
  // Saves nothing when the chain has no GL (it was made without a current 4.5 context).
  explicit GlStateGuard(const Chain& chain);
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  const Chain& chain_;
  std::unique_ptr<GlStateScope> scope_;
};

}  // namespace pfx::host
