#pragma once
// When an FX effect's uniform values may be compiled in as constants (ReShade's performance mode,
// made automatic), the rule both runtimes follow: the values a specialised program would hold are
// every uniform no frame source fills (the user's parameters and plain initial values); they
// count as settled from the first frame (a renderer, a video host or a farm job never changes
// them), and after a change once they have held still for kSettleSeconds (a slider being dragged
// keeps its uniform live, so no frame waits for a compile per value). PFX_FX_SPECIALISE=0 keeps
// every uniform live.
#include <chrono>

#include "effect_compiler.hpp"
#include "fx_uniform_values.hpp"

namespace pfx_fx {

// The values a specialised program would hold: each uniform without a frame source, else empty.
pfx::fx::UniformConstants held_values(const pfx::fx::EffectModel& model, const UniformValues& values);

class SettledValues {
 public:
  static constexpr double kSettleSeconds = 0.5;

  SettledValues();  // reads PFX_FX_SPECIALISE
  bool enabled() const { return enabled_; }
  // Once a frame, with that frame's held values (empty when not enabled).
  struct Frame {
    bool first = false;    // the first frame since reset()
    bool settled = false;  // the values may be compiled in
  };
  Frame observe(const pfx::fx::UniformConstants& held);
  // A new compile of the effect: the next frame is a first one again.
  void reset();

 private:
  bool enabled_ = true;
  pfx::fx::UniformConstants last_held_;
  std::chrono::steady_clock::time_point last_change_{};
  bool first_frame_ = true;
};

}  // namespace pfx_fx
