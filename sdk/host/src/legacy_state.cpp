#include "legacy_state.hpp"

#include <glad/gl.h>

namespace pfx::host {
namespace {

// Compatibility-profile enums, which a core loader does not define (values from the GL registry).
constexpr GLenum kAlphaTest = 0x0BC0;
constexpr GLenum kPolygonStipple = 0x0B42;
constexpr GLenum kClampFragmentColor = 0x891B;

void set_enabled(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

}  // namespace

LegacyStateScope::LegacyStateScope(bool compatibility_profile) : active_(compatibility_profile) {
  if (!active_) return;
  alpha_test_ = glIsEnabled(kAlphaTest);
  polygon_stipple_ = glIsEnabled(kPolygonStipple);
  glGetIntegerv(kClampFragmentColor, &clamp_fragment_color_);
  glDisable(kAlphaTest);
  glDisable(kPolygonStipple);
  glClampColor(kClampFragmentColor, GL_FIXED_ONLY);
}

LegacyStateScope::~LegacyStateScope() {
  if (!active_) return;
  set_enabled(kAlphaTest, alpha_test_);
  set_enabled(kPolygonStipple, polygon_stipple_);
  glClampColor(kClampFragmentColor, static_cast<GLenum>(clamp_fragment_color_));
}

}  // namespace pfx::host
