#pragma once
// FX's formats and states in Vulkan's terms: texture formats (with the sRGB form an RGBA8
// texture is sampled and written through when a sampler or pass asks for sRGB), sampler states,
// blend and stencil states and topologies. The same choices as the GL runtime's, so a technique means the
// same on both.
#include <vulkan/vulkan.h>

#include "model/effect_model.hpp"

namespace pfx::fx::vulkan {

VkFormat vk_format(TextureFormat format);
// The sRGB form of a format, or VK_FORMAT_UNDEFINED when it has none.
VkFormat srgb_form(VkFormat format);

// A sampler with the FX sampler's states. Integer textures are read texel by texel, as in GL;
// the LOD bias is held to the device's limit.
VkSamplerCreateInfo sampler_info(const SamplerInfo& sampler, bool integer_texture, float max_lod_bias);

VkPipelineColorBlendAttachmentState blend_state(const BlendTarget& blend, bool integer_target);
// The same operations on front and back faces, as ReShade applies them.
VkStencilOpState stencil_state(const StencilState& stencil);
VkPrimitiveTopology vk_topology(Topology topology);

}  // namespace pfx::fx::vulkan
