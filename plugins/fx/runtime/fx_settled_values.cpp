#include "fx_settled_values.hpp"

#include <cstdlib>
#include <cstring>

namespace pfx_fx {

pfx::fx::UniformConstants held_values(const pfx::fx::EffectModel& model, const UniformValues& values) {
  pfx::fx::UniformConstants held(model.uniforms.size());
  for (std::size_t i = 0; i < model.uniforms.size(); ++i)
    if (model.uniforms[i].source.empty()) held[i] = values.of(static_cast<int>(i));
  return held;
}

SettledValues::SettledValues() {
  const char* setting = std::getenv("PFX_FX_SPECIALISE");
  enabled_ = !(setting && std::strcmp(setting, "0") == 0);
}

SettledValues::Frame SettledValues::observe(const pfx::fx::UniformConstants& held) {
  const auto now = std::chrono::steady_clock::now();
  if (held != last_held_) {
    last_held_ = held;
    if (!first_frame_) last_change_ = now;
  }
  Frame frame;
  frame.first = first_frame_;
  frame.settled = first_frame_ || std::chrono::duration<double>(now - last_change_).count() >= kSettleSeconds;
  first_frame_ = false;
  return frame;
}

void SettledValues::reset() {
  last_held_.clear();
  first_frame_ = true;
}

}  // namespace pfx_fx
