// An application's frame gives the chain its colour and, when the depth buffer is judged usable,
// its depth; never normals, albedo or lights. What each effect needs is what it declares
// (Chain::inputs_needed), not a list of names here: an effect that needs what the frame lacks is
// turned off for as long as it lacks it, with one log line each time that changes, instead of
// failing the frame; and a chain nobody chose leaves out for good the effects that need what no
// application frame can give.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>

namespace pfx::inject {

class InputFit {
 public:
  // After the chain was (re)built: remembers which effects the user switched on. With
  // `default_chain`, removes those that need more than colour and depth (`frame` stands for the
  // frames to come) and says so in one line. False with *error when an effect's declare fails.
  bool start(host::Chain& chain, bool default_chain, const pfx_frame& frame, std::vector<std::string>* messages,
             std::string* error);
  // Before a frame: switches effects off and on for what `frame.inputs` holds; does nothing while
  // that is what it was last time. `lacking_depth` says why depth is missing, for the log.
  bool fit(host::Chain& chain, const pfx_frame& frame, const std::string& lacking_depth,
           std::vector<std::string>* messages, std::string* error);
  // Whether the user switched the effect at `index` on (the chain's own flag also holds fit's).
  bool wanted(size_t index) const { return wanted_.at(index); }

 private:
  std::vector<bool> wanted_;
  std::vector<uint32_t> missing_;  // per effect: the inputs it lacked when last fitted
  uint32_t fitted_inputs_ = 0;
  bool fitted_ = false;
};

}  // namespace pfx::inject
