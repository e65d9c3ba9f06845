#include "vk_frame_alpha.hpp"

#include <vector>

#include "vk_pipelines.hpp"

namespace pfx::fx::vulkan {
namespace {

// The full-screen triangle, as ReShade.fxh's PostProcessVS draws it.
constexpr const char* kVertex = R"(#version 450
void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kFragment = R"(#version 450
layout(set = 0, binding = 0) uniform sampler2D original;
layout(location = 0) out vec4 color;
void main() { color = vec4(0.0, 0.0, 0.0, texelFetch(original, ivec2(gl_FragCoord.xy), 0).a); }
)";

}  // namespace

std::string FrameAlpha::create(const Device& d, const Image& original, const Image& target, VkPipelineCache cache) {
  d_ = &d;
  width_ = target.width, height_ = target.height;
  const char* sources[2] = {kVertex, kFragment};
  for (int i = 0; i < 2; ++i) {
    const std::string log = create_shader_module(d, sources[i], i == 0 ? SpirvStage::kVertex : SpirvStage::kFragment, modules_[i]);
    if (!log.empty()) return "the alpha pass: " + log;
  }
  VkSamplerCreateInfo sampler{};
  sampler.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;  // nearest, clamped: texelFetch ignores it anyway
  if (d.vkCreateSampler(d.device, &sampler, nullptr, &sampler_) != VK_SUCCESS) return "vkCreateSampler failed";
  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo set_layout{};
  set_layout.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  set_layout.bindingCount = 1;
  set_layout.pBindings = &binding;
  if (d.vkCreateDescriptorSetLayout(d.device, &set_layout, nullptr, &set_layout_) != VK_SUCCESS) return "vkCreateDescriptorSetLayout failed";
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo pool{};
  pool.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pool.maxSets = 1;
  pool.poolSizeCount = 1;
  pool.pPoolSizes = &size;
  if (d.vkCreateDescriptorPool(d.device, &pool, nullptr, &pool_) != VK_SUCCESS) return "vkCreateDescriptorPool failed";
  VkDescriptorSetAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocate.descriptorPool = pool_;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &set_layout_;
  if (d.vkAllocateDescriptorSets(d.device, &allocate, &set_) != VK_SUCCESS) return "vkAllocateDescriptorSets failed";
  const VkDescriptorImageInfo image{sampler_, original.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set_;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &image;
  d.vkUpdateDescriptorSets(d.device, 1, &write, 0, nullptr);
  VkPipelineLayoutCreateInfo layout{};
  layout.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layout.setLayoutCount = 1;
  layout.pSetLayouts = &set_layout_;
  if (d.vkCreatePipelineLayout(d.device, &layout, nullptr, &layout_) != VK_SUCCESS) return "vkCreatePipelineLayout failed";

  PassInfo alpha_only;  // a full-screen triangle, writing alpha only
  alpha_only.blend[0].write_mask = VK_COLOR_COMPONENT_A_BIT;
  GraphicsPlan plan;
  plan.pass = &alpha_only;
  plan.vertex = modules_[0], plan.fragment = modules_[1];
  plan.layout = layout_;
  plan.attachments = {{target.format, false}};
  plan.viewport_width = plan.area_width = width_;
  plan.viewport_height = plan.area_height = height_;
  render_pass_ = plan.render_pass = create_render_pass(d, plan.attachments, false);
  if (!render_pass_) return "vkCreateRenderPass failed";
  VkFramebufferCreateInfo framebuffer{};
  framebuffer.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  framebuffer.renderPass = render_pass_;
  framebuffer.attachmentCount = 1;
  framebuffer.pAttachments = &target.view;
  framebuffer.width = static_cast<std::uint32_t>(width_);
  framebuffer.height = static_cast<std::uint32_t>(height_);
  framebuffer.layers = 1;
  if (d.vkCreateFramebuffer(d.device, &framebuffer, nullptr, &framebuffer_) != VK_SUCCESS) return "vkCreateFramebuffer failed";
  pipeline_ = create_graphics_pipeline(d, plan, cache);
  return pipeline_ ? "" : "vkCreateGraphicsPipelines failed";
}

void FrameAlpha::record(VkCommandBuffer commands, Image& original, Image& target) {
  const Device& d = *d_;
  use_for_sampling(d, commands, original);
  use_as_attachment(d, commands, target);
  VkRenderPassBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  begin.renderPass = render_pass_;
  begin.framebuffer = framebuffer_;
  begin.renderArea = {{0, 0}, {static_cast<std::uint32_t>(width_), static_cast<std::uint32_t>(height_)}};
  d.vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  d.vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  d.vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0, nullptr);
  d.vkCmdDraw(commands, 3, 1, 0, 0);
  d.vkCmdEndRenderPass(commands);
}

void FrameAlpha::destroy(const Device& d) {
  if (pipeline_) d.vkDestroyPipeline(d.device, pipeline_, nullptr);
  if (framebuffer_) d.vkDestroyFramebuffer(d.device, framebuffer_, nullptr);
  if (render_pass_) d.vkDestroyRenderPass(d.device, render_pass_, nullptr);
  if (layout_) d.vkDestroyPipelineLayout(d.device, layout_, nullptr);
  if (pool_) d.vkDestroyDescriptorPool(d.device, pool_, nullptr);
  if (set_layout_) d.vkDestroyDescriptorSetLayout(d.device, set_layout_, nullptr);
  if (sampler_) d.vkDestroySampler(d.device, sampler_, nullptr);
  for (VkShaderModule& m : modules_)
    if (m) d.vkDestroyShaderModule(d.device, m, nullptr), m = VK_NULL_HANDLE;
  *this = FrameAlpha{};
}

}  // namespace pfx::fx::vulkan
