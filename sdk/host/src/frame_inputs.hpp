// The frame inputs a pass may read by name ("color", "depth", ...) and their PFX_INPUT_* bits:
// shared by the declaration checks (the names are reserved) and the planner.
#pragma once

#include <cstdint>
#include <string>

#include <pfx/effect.h>

namespace pfx::host {

struct FrameInputName {
  const char* name;
  uint32_t bit;
};
inline constexpr FrameInputName kFrameInputs[] = {
    {PFX_INPUT_NAME_COLOR, PFX_INPUT_COLOR},       {PFX_INPUT_NAME_DEPTH, PFX_INPUT_DEPTH},
    {PFX_INPUT_NAME_NORMAL, PFX_INPUT_NORMAL},     {PFX_INPUT_NAME_ALBEDO, PFX_INPUT_ALBEDO},
    {PFX_INPUT_NAME_EMISSIVE, PFX_INPUT_EMISSIVE},
};

// Null for a name that is not a frame input.
inline const FrameInputName* find_frame_input(const std::string& name) {
  for (const auto& input : kFrameInputs)
    if (name == input.name) return &input;
  return nullptr;
}

}  // namespace pfx::host
