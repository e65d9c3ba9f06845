#pragma once
// The states a texture, sampler, storage or pass block may set (REFERENCE.md), with the kind of
// value each takes, so a misspelt state or value is an error at compile time, not a surprise at
// run time.
#include <string>
#include <vector>

namespace pfx::fx {

enum class StateOwner { kTexture, kSampler, kStorage, kPass };

struct StateRule {
  enum class Kind { kSize, kNumber, kBool, kEnum, kTexture, kFunction, kMask } kind = Kind::kNumber;
  const std::vector<std::string>* values = nullptr;  // kEnum: the names it accepts
};

// The rule for `name` ("BlendOp3" finds BlendOp's), or nullptr for a state the owner lacks.
const StateRule* find_state(StateOwner owner, const std::string& name);
const char* owner_name(StateOwner owner);

}  // namespace pfx::fx
