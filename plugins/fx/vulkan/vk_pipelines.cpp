#include "vk_pipelines.hpp"

#include "vk_states.hpp"

namespace pfx::fx::vulkan {

std::string create_shader_module(const Device& d, const std::string& glsl, SpirvStage stage, VkShaderModule& out) {
  std::vector<std::uint32_t> words;
  std::string log;
  if (!compile_spirv(glsl, stage, words, log)) return log.empty() ? "glslang failed" : log;
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = words.size() * 4;
  info.pCode = words.data();
  return d.vkCreateShaderModule(d.device, &info, nullptr, &out) == VK_SUCCESS ? "" : "vkCreateShaderModule failed";
}

VkRenderPass create_render_pass(const Device& d, const std::vector<AttachmentPlan>& attachments, bool clear, VkFormat stencil) {
  std::vector<VkAttachmentDescription> descriptions;
  std::vector<VkAttachmentReference> references;
  for (const AttachmentPlan& a : attachments) {
    VkAttachmentDescription description{};
    description.format = a.format;
    description.samples = VK_SAMPLE_COUNT_1_BIT;
    description.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    description.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    description.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    description.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    description.initialLayout = description.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    references.push_back({static_cast<std::uint32_t>(descriptions.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    descriptions.push_back(description);
  }
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = static_cast<std::uint32_t>(references.size());
  subpass.pColorAttachments = references.data();
  const VkAttachmentReference stencil_reference{static_cast<std::uint32_t>(descriptions.size()), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  if (stencil != VK_FORMAT_UNDEFINED) {
    VkAttachmentDescription description{};
    description.format = stencil;
    description.samples = VK_SAMPLE_COUNT_1_BIT;
    description.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // no depth test: a combined format's depth is unused
    description.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    description.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    description.stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
    description.initialLayout = description.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    descriptions.push_back(description);
    subpass.pDepthStencilAttachment = &stencil_reference;
  }
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = static_cast<std::uint32_t>(descriptions.size());
  info.pAttachments = descriptions.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass out = VK_NULL_HANDLE;
  return d.vkCreateRenderPass(d.device, &info, nullptr, &out) == VK_SUCCESS ? out : VK_NULL_HANDLE;
}

VkPipeline create_graphics_pipeline(const Device& d, const GraphicsPlan& plan, VkPipelineCache cache) {
  VkPipelineShaderStageCreateInfo stages[2]{};
  for (int i = 0; i < 2; ++i) {
    stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[i].module = i == 0 ? plan.vertex : plan.fragment;
    stages[i].pName = "main";
  }
  VkPipelineVertexInputStateCreateInfo vertex_input{};
  vertex_input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = vk_topology(plan.pass->topology);
  VkViewport viewport{0, 0, static_cast<float>(plan.viewport_width), static_cast<float>(plan.viewport_height), 0, 1};
  VkRect2D scissor{{0, 0}, {static_cast<std::uint32_t>(plan.area_width), static_cast<std::uint32_t>(plan.area_height)}};
  VkPipelineViewportStateCreateInfo viewport_state{};
  viewport_state.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport_state.viewportCount = viewport_state.scissorCount = 1;
  viewport_state.pViewports = &viewport;
  viewport_state.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkPipelineColorBlendAttachmentState> blends;
  for (std::size_t i = 0; i < plan.attachments.size(); ++i) blends.push_back(blend_state(plan.pass->blend[i], plan.attachments[i].integer));
  VkPipelineColorBlendStateCreateInfo blend{};
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blend.attachmentCount = static_cast<std::uint32_t>(blends.size());
  blend.pAttachments = blends.data();
  VkPipelineDepthStencilStateCreateInfo depth_stencil{};
  depth_stencil.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  depth_stencil.stencilTestEnable = plan.stencil ? VK_TRUE : VK_FALSE;
  depth_stencil.front = depth_stencil.back = stencil_state(plan.pass->stencil);
  depth_stencil.maxDepthBounds = 1.0f;
  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport_state;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blend;
  info.pDepthStencilState = plan.stencil ? &depth_stencil : nullptr;
  info.layout = plan.layout;
  info.renderPass = plan.render_pass;
  VkPipeline out = VK_NULL_HANDLE;
  return d.vkCreateGraphicsPipelines(d.device, cache, 1, &info, nullptr, &out) == VK_SUCCESS ? out : VK_NULL_HANDLE;
}

VkPipeline create_compute_pipeline(const Device& d, VkShaderModule module, VkPipelineLayout layout, VkPipelineCache cache) {
  VkComputePipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline out = VK_NULL_HANDLE;
  return d.vkCreateComputePipelines(d.device, cache, 1, &info, nullptr, &out) == VK_SUCCESS ? out : VK_NULL_HANDLE;
}

}  // namespace pfx::fx::vulkan
