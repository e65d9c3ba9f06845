#pragma once
// Parameters whose default or slider range is written in terms of the frame's size
// (`uniform int iHeight < ui_max = BUFFER_HEIGHT; > = BUFFER_HEIGHT;`). ReShade compiles an effect
// for the back buffer it runs on, so such a default is the frame's own height. pfx lists every
// technique once, at a nominal size, and flags these parameters (PFX_PARAM_FOLLOWS_FRAME_SIZE);
// an instance compiles at its frame's size and resolves the host's values against that compile:
//   - a value equal to the listed default was not set by anyone: it becomes the frame's default;
//   - any other value was set: it stays, clamped into the frame's slider range (said once).
#include <set>
#include <string>
#include <vector>

#include <pfx/params.h>

#include "fx_parameters.hpp"
#include "model/effect_model.hpp"

namespace pfx_fx {

// Flags every parameter of `listed` whose default or display range differs in `other`, the same
// file's parameters compiled at another frame size. Nothing is flagged when the two do not list
// the same parameters (a file that declares other uniforms at another size).
void mark_frame_size_dependence(ParamTable& listed, const ParamTable& other);

// Builds the parameters of `model` (the file compiled at some frame size) with the flags of
// `listed`: what the sources factory's params_at hands out.
void build_params_at_size(const pfx::fx::EffectModel& model, const ParamTable& listed, ParamTable& out);

class FrameParams {
 public:
  // For a new compile of the file (`model`, at width x height).
  void reset(const pfx::fx::EffectModel& model, const ParamTable& listed, int width, int height);
  // The values the instance runs with: `host` (one per listed parameter) with the flagged ones
  // resolved as above. A clamp is reported once per parameter and size through `notes`.
  const pfx_value* resolve(const ParamTable& listed, const pfx_value* host, std::vector<std::string>& notes);

 private:
  ParamTable at_size_;
  bool any_follows_ = false;
  std::string size_;  // "640x360", for the notes
  std::vector<pfx_value> values_;
  std::set<std::string> told_;
};

}  // namespace pfx_fx
