#pragma once
// The FX plugin's effects on a Vulkan device ("pfx.vulkan_effects/1", pfx/vulkan_effects.h): the
// same techniques, compiled at the frame's size and run by the Vulkan runtime for FX
// (plugins/fx/vulkan), with the uniforms the GL instance would give them (parameters, those that
// follow the frame size, the frame's sources). Textures' image files are found as the GL side
// finds them. Not yet: a host's preprocessor definitions (pfx.sources/1's set_definitions names
// GL instances only), reloading an edited file, the frame's depth.
#include <pfx/vulkan_effects.h>

namespace pfx_fx {

extern const pfx_vulkan_effect_factory kVulkanEffects;

}  // namespace pfx_fx
