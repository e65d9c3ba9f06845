#pragma once
// The values of an effect's uniforms for one frame: initial values, the user's parameters, and
// the special sources ReShade fills from the frame (timer, frametime, framecount, random,
// pingpong, date, and the input sources, which hold constants here: pfx has no keyboard or mouse).
#include <cstdint>
#include <vector>

#include <pfx/effect.h>

#include "fx_parameters.hpp"
#include "model/effect_model.hpp"

namespace pfx_fx {

class UniformValues {
 public:
  // Starts over for a model (a compile of the file at a frame size, or an edit of it): initial
  // values, and where each parameter of `params` lands in this model's uniforms, found by name
  // (a parameter whose uniform is gone is ignored).
  void reset(const pfx::fx::EffectModel& model, const ParamTable& params);
  // Fills every uniform for this frame. `depth_available` answers source "bufready_depth".
  void update(const pfx::fx::EffectModel& model, const ParamTable& params, const pfx_value* values, const pfx_frame& frame,
              bool depth_available);
  const std::vector<double>& of(int uniform) const { return values_[static_cast<std::size_t>(uniform)]; }
  const std::vector<std::vector<double>>& all() const { return values_; }  // per model uniform

 private:
  std::vector<std::vector<double>> values_;
  std::vector<double> pingpong_;  // position and direction per uniform
  std::vector<int> param_uniform_;  // per parameter: its uniform's index in the model, or -1
  double last_time_ = -1;
};

}  // namespace pfx_fx
