// Technique::record: a frame's commands (vk_technique.hpp).
#include <algorithm>

#include "vk_technique.hpp"

namespace pfx::fx::vulkan {

void Technique::record(VkCommandBuffer commands, const Frame& frame, const std::vector<std::vector<double>>& uniforms,
                       const UniformConstants* constants) {
  const Device& d = *d_;
  const Specialised* specialised = constants ? specialised_for(*constants) : nullptr;
  if (!started_) {
    for (std::size_t i = 0; i < images_.size(); ++i)
      if (images_[i].image) clear_image(d, commands, images_[i], static_cast<int>(i) == depth_image_);
    uploads_.record(commands, images_);
    started_ = true;
  }
  Image& stencil = images_[static_cast<std::size_t>(stencil_image_)];
  if (stencil.image) clear_image(d, commands, stencil);  // the technique starts: zeros, as in ReShade
  record_uniforms(commands, uniforms);
  // The caller's image, tracked as ours for the length of the frame.
  Image caller;
  caller.image = frame.image;
  caller.format = frame.format;
  caller.width = width_, caller.height = height_;
  caller.layout = frame.layout;
  caller.access = VK_ACCESS_MEMORY_WRITE_BIT;
  caller.stage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
  Image* back_buffers = &images_[static_cast<std::size_t>(back_buffer_image_)];
  copy_image(d, commands, caller, back_buffers[0]);
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    const VkPipeline chosen = specialised ? specialised->pipelines[i] : VK_NULL_HANDLE;
    record_pass(commands, passes_[i], chosen ? chosen : passes_[i].pipeline);
  }
  // A technique that never writes the back buffer leaves the frame as it was.
  if (last_back_buffer_ != 0) {
    if (frame.keep_alpha) frame_alpha_.record(commands, back_buffers[0], back_buffers[last_back_buffer_]);
    copy_image(d, commands, back_buffers[last_back_buffer_], caller);
  }
  use_image(d, commands, caller, frame.final_layout, VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
}

void Technique::record_uniforms(VkCommandBuffer commands, const std::vector<std::vector<double>>& uniforms) {
  if (!block_.size) return;
  const Device& d = *d_;
  pack_uniform_block(*model_, block_, uniforms, block_bytes_);
  // The last frame's passes read the block: they finish before it is written, and this frame's
  // passes read what is written (the values travel inside the command buffer).
  VkBufferMemoryBarrier b{};
  b.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = uniform_buffer_;
  b.size = VK_WHOLE_SIZE;
  b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  d.vkCmdPipelineBarrier(commands, kShaderStages, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 1, &b, 0, nullptr);
  d.vkCmdUpdateBuffer(commands, uniform_buffer_, 0, block_.size, block_bytes_.data());
  b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_UNIFORM_READ_BIT;
  d.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, kShaderStages, 0, 0, nullptr, 1, &b, 0, nullptr);
}

void Technique::record_pass(VkCommandBuffer commands, Pass& pass, VkPipeline pipeline) {
  const Device& d = *d_;
  auto image = [&](int index) -> Image& { return images_[static_cast<std::size_t>(index)]; };
  const bool stored_mips = pass.compute && pass.info->generate_mipmaps;
  // A pass that may leave pixels of the back buffer unwritten starts from the picture (copied
  // before the picture is made ready to sample).
  if (pass.copy_first) copy_image(d, commands, image(back_buffer_image_ + pass.back_buffer), image(pass.targets[0]));
  for (int s : pass.stored) use_as_storage(d, commands, image(s));
  for (int s : pass.sampled)
    if (std::find(pass.stored.begin(), pass.stored.end(), s) == pass.stored.end()) use_for_sampling(d, commands, image(s));
  if (pass.compute) {
    d.vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    d.vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pass.layout, 0, 1, &pass.set, 0, nullptr);
    const int* groups = pass.info->dispatch;
    d.vkCmdDispatch(commands, static_cast<std::uint32_t>(groups[0]), static_cast<std::uint32_t>(groups[1]), static_cast<std::uint32_t>(groups[2]));
    if (stored_mips)
      for (int s : pass.stored) generate_mips(d, commands, image(s));
    return;
  }
  for (int t : pass.targets) use_as_attachment(d, commands, image(t));
  if (pass.stencil) use_as_stencil(d, commands, image(stencil_image_));
  // Zero bits in every format, for a pass that clears its targets.
  std::vector<VkClearValue> clears(pass.info->clear_render_targets ? pass.targets.size() : 0, VkClearValue{});
  VkRenderPassBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  begin.renderPass = pass.render_pass;
  begin.framebuffer = pass.framebuffer;
  begin.renderArea = {{0, 0}, {static_cast<std::uint32_t>(pass.area_width), static_cast<std::uint32_t>(pass.area_height)}};
  begin.clearValueCount = static_cast<std::uint32_t>(clears.size());
  begin.pClearValues = clears.data();
  d.vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  d.vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  d.vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.layout, 0, 1, &pass.set, 0, nullptr);
  d.vkCmdDraw(commands, static_cast<std::uint32_t>(pass.info->vertex_count), 1, 0, 0);
  d.vkCmdEndRenderPass(commands);
  if (!pass.writes_back_buffer && pass.info->generate_mipmaps)
    for (int t : pass.targets) generate_mips(d, commands, image(t));
}

}  // namespace pfx::fx::vulkan
