// A compatibility-profile context (glxgears asks for one) keeps fixed-function state that still
// applies to a program's fragments: the alpha test, polygon stipple and fragment colour clamping.
// Core-profile code never sets it, so GlStateScope saves it in such a context, turns it off for
// the chain and puts it back.
#pragma once

namespace pfx::host {

class LegacyStateScope {
 public:
  explicit LegacyStateScope(bool compatibility_profile);
  ~LegacyStateScope();
  LegacyStateScope(const LegacyStateScope&) = delete;
  LegacyStateScope& operator=(const LegacyStateScope&) = delete;

 private:
  bool active_ = false;
  unsigned char alpha_test_ = 0, polygon_stipple_ = 0;
  int clamp_fragment_color_ = 0;
};

}  // namespace pfx::host
