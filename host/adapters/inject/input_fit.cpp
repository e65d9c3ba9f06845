#include "input_fit.hpp"

#include <pfx/host/frame_plan.hpp>

namespace pfx::inject {
namespace {

// What an application's frame can give at best.
constexpr uint32_t kApplicationInputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH;

}  // namespace

bool InputFit::start(host::Chain& chain, bool default_chain, const pfx_frame& frame,
                     std::vector<std::string>* messages, std::string* error) {
  if (default_chain) {
    pfx_frame best = frame;
    best.inputs = kApplicationInputs;
    std::string left_out;
    for (size_t i = chain.size(); i-- > 0;) {
      uint32_t needed = 0;
      if (!chain.inputs_needed(i, best, &needed, error)) return false;
      const uint32_t missing = needed & ~kApplicationInputs;
      if (!missing) continue;
      left_out = chain.instance_name(i) + " (needs " + host::frame_input_names(missing) + ")" +
                 (left_out.empty() ? "" : ", ") + left_out;
      chain.remove(i);
    }
    if (!left_out.empty())
      messages->push_back("left out of the default chain, as an application's frame cannot give what they need: " +
                          left_out);
  }
  wanted_.assign(chain.size(), false);
  for (size_t i = 0; i < chain.size(); ++i) wanted_[i] = chain.enabled(i);
  missing_.assign(chain.size(), 0);
  fitted_ = false;
  return true;
}

bool InputFit::fit(host::Chain& chain, const pfx_frame& frame, const std::string& lacking_depth,
                   std::vector<std::string>* messages, std::string* error) {
  if (fitted_ && frame.inputs == fitted_inputs_) return true;
  for (size_t i = 0; i < chain.size(); ++i) {
    if (!wanted_[i]) continue;
    uint32_t needed = 0;
    if (!chain.inputs_needed(i, frame, &needed, error)) return false;
    const uint32_t missing = needed & ~frame.inputs;
    chain.set_enabled(i, missing == 0);
    if (missing == missing_[i]) continue;
    if (missing) {
      std::string why = (missing & PFX_INPUT_DEPTH) ? lacking_depth : "";
      if (missing & ~PFX_INPUT_DEPTH) why += std::string(why.empty() ? "" : "; ") + "an application's frame cannot give the rest";
      messages->push_back(chain.instance_name(i) + " off: needs " + host::frame_input_names(missing) + " (" + why + ")");
    } else {
      messages->push_back(chain.instance_name(i) + " on again: the frame has what it needs");
    }
    missing_[i] = missing;
  }
  fitted_inputs_ = frame.inputs;
  fitted_ = true;
  return true;
}

}  // namespace pfx::inject
