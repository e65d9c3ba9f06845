#pragma once
// The Vulkan objects that draw or dispatch one FX pass: its render pass (one colour attachment
// per render target, loaded or cleared as ClearRenderTargets says, kept in the attachment layout:
// the images' barriers are recorded around it; the stencil buffer after them when the pass tests
// it), its graphics pipeline (topology, blend states and write masks per target, the stencil test,
// no depth test, no culling: what FX passes are) or its compute pipeline.
// Every pipeline goes through the VkPipelineCache it is given.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "codegen/spirv_module.hpp"
#include "model/effect_model.hpp"
#include "vk_device.hpp"

namespace pfx::fx::vulkan {

// A shader module from Vulkan GLSL, compiled by glslang: "" or glslang's log (or what failed).
std::string create_shader_module(const Device& d, const std::string& glsl, SpirvStage stage, VkShaderModule& out);

struct AttachmentPlan {
  VkFormat format = VK_FORMAT_UNDEFINED;
  bool integer = false;
};

// `stencil`: the format of the technique's stencil buffer, attached after the colours and kept from
// pass to pass (VK_FORMAT_UNDEFINED: none).
VkRenderPass create_render_pass(const Device& d, const std::vector<AttachmentPlan>& attachments, bool clear,
                                VkFormat stencil = VK_FORMAT_UNDEFINED);

struct GraphicsPlan {
  const PassInfo* pass = nullptr;
  VkShaderModule vertex = VK_NULL_HANDLE, fragment = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::vector<AttachmentPlan> attachments;
  int viewport_width = 1, viewport_height = 1;  // the first target's size
  int area_width = 1, area_height = 1;          // what every target has
  bool stencil = false;                         // the pass tests the stencil buffer the render pass holds
};

VkPipeline create_graphics_pipeline(const Device& d, const GraphicsPlan& plan, VkPipelineCache cache);
VkPipeline create_compute_pipeline(const Device& d, VkShaderModule module, VkPipelineLayout layout, VkPipelineCache cache);

}  // namespace pfx::fx::vulkan
