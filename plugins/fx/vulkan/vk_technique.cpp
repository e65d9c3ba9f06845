#include "vk_technique.hpp"

#include <algorithm>

#include "model/full_screen_pass.hpp"
#include "vk_pipelines.hpp"
#include "vk_states.hpp"

namespace pfx::fx::vulkan {
namespace {

// The plain form of an 8-bit sRGB frame format: the back buffers hold its codes, and an sRGB view
// of them decodes for the samplers that ask.
VkFormat codes_form(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_SRGB: return VK_FORMAT_R8G8B8A8_UNORM;
    case VK_FORMAT_B8G8R8A8_SRGB: return VK_FORMAT_B8G8R8A8_UNORM;
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32: return VK_FORMAT_A8B8G8R8_UNORM_PACK32;
    default: return format;
  }
}

bool contains(const std::vector<int>& list, int value) { return std::find(list.begin(), list.end(), value) != list.end(); }

// A pass as messages name it: by its name, or by its place in the technique (from 0).
std::string pass_label(const PassInfo& pass, std::size_t index) {
  return pass.name.empty() ? "pass " + std::to_string(index) : "pass '" + pass.name + "'";
}

// The back buffer a pass that writes it draws into: never the frame's copy (0), whose alpha is put
// back at the end.
int next_back_buffer(int current) { return current == 1 ? 2 : 1; }

}  // namespace

Technique::Status Technique::create(const Device& device, const CompiledEffect& effect, int technique, int width, int height,
                                    VkFormat frame_format, VkPipelineCache cache, const TexelLoader& load_texels, std::string& message) {
  destroy();
  d_ = &device;
  cache_ = cache;
  model_ = &effect.model;
  if (technique < 0 || static_cast<std::size_t>(technique) >= model_->techniques.size())
    return message = "the effect has no technique " + std::to_string(technique), Status::kFailed;
  technique_ = &model_->techniques[static_cast<std::size_t>(technique)];
  width_ = width, height_ = height;
  message = unsupported_reason(*model_, technique);
  if (!message.empty()) return Status::kUnsupported;
  Diagnostics diagnostics(effect.front->names);
  std::vector<GeneratedPass> generated;
  for (const PassInfo& pass : technique_->passes)
    generated.push_back(generate_pass(effect.front->unit, *model_, pass, diagnostics, nullptr, GlslDialect::kVulkan));
  if (diagnostics.has_errors()) return message = diagnostics.format_all(), Status::kFailed;
  block_ = layout_uniform_block(*model_);
  // vkCmdUpdateBuffer takes at most 64 KiB; FX blocks are a few hundred bytes.
  if (block_.size > 65536) return message = "the uniforms take more than 64 KiB", Status::kUnsupported;
  message = create_images(frame_format, load_texels);
  for (std::size_t i = 0; message.empty() && i < model_->samplers.size(); ++i) {
    const SamplerInfo& s = model_->samplers[i];
    const int image = image_of_texture(s.texture, 0);
    const VkSamplerCreateInfo info = sampler_info(s, image >= 0 && images_[static_cast<std::size_t>(image)].integer,
                                                  d_->properties.limits.maxSamplerLodBias);
    samplers_.push_back(VK_NULL_HANDLE);
    if (d_->vkCreateSampler(d_->device, &info, nullptr, &samplers_.back()) != VK_SUCCESS) message = "vkCreateSampler failed";
  }
  if (message.empty()) message = create_pool();
  if (message.empty()) message = create_uniform_buffer();
  int back_buffer = 0;
  for (std::size_t i = 0; message.empty() && i < generated.size(); ++i) {
    passes_.emplace_back();
    passes_.back().back_buffer = back_buffer;
    message = create_pass(i, generated[i]);
    if (passes_.back().writes_back_buffer) back_buffer = next_back_buffer(back_buffer);
  }
  last_back_buffer_ = back_buffer;
  if (message.empty() && last_back_buffer_ != 0)
    message = frame_alpha_.create(*d_, images_[static_cast<std::size_t>(back_buffer_image_)],
                                  images_[static_cast<std::size_t>(back_buffer_image_ + last_back_buffer_)], cache);
  if (message.empty()) return Status::kOk;
  destroy();
  return Status::kFailed;
}

std::string Technique::unsupported_reason(const EffectModel& model, int technique) {
  const TechniqueInfo& info = model.techniques.at(static_cast<std::size_t>(technique));
  for (std::size_t index = 0; index < info.passes.size(); ++index) {
    const PassInfo& pass = info.passes[index];
    for (int i = 0; i < pass.render_target_count; ++i)
      if (pass.render_targets[i] >= 0 && model.textures[static_cast<std::size_t>(pass.render_targets[i])].dimension != 2)
        return pass_label(pass, index) + " renders to a texture that is not 2D, which the Vulkan runtime does not run yet";
  }
  return "";
}

std::string Technique::create_images(VkFormat frame_format, const TexelLoader& load_texels) {
  const std::size_t textures = model_->textures.size();
  images_.assign(textures + 5, Image{});
  back_buffer_image_ = static_cast<int>(textures);
  depth_image_ = back_buffer_image_ + 3;
  stencil_image_ = depth_image_ + 1;
  for (std::size_t i = 0; i < textures; ++i) {
    const TextureInfo& t = model_->textures[i];
    if (t.semantic != TextureSemantic::kNone) continue;  // the back buffer's or the depth's images
    ImageShape shape;
    shape.type = t.dimension == 1 ? VK_IMAGE_TYPE_1D : t.dimension == 3 ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    shape.width = t.width, shape.height = t.height, shape.depth = t.depth, shape.levels = t.mip_levels;
    shape.format = vk_format(t.format);
    shape.integer = integer_class(t.format) != 0;
    for (const StorageInfo& s : model_->storages) shape.storage = shape.storage || s.texture == static_cast<int>(i);
    std::string error = create_image(*d_, shape, images_[i]);
    if (error.empty() && !t.source.empty()) {
      TextureTexels texels;
      if (!load_texels || !load_texels(t, texels, error)) error = error.empty() ? "no loader for its image file" : error;
      else error = uploads_.add(*d_, images_[i], static_cast<int>(i), texels);
    }
    if (!error.empty()) return "texture '" + t.name + "' (" + format_name(t.format) + "): " + error;
  }
  ImageShape back;
  back.width = width_, back.height = height_;
  back.format = codes_form(frame_format);
  for (int b = 0; b < 3; ++b) {
    const std::string error = create_image(*d_, back, images_[static_cast<std::size_t>(back_buffer_image_ + b)]);
    if (!error.empty()) return "the back buffer: " + error;
  }
  ImageShape depth;
  depth.format = VK_FORMAT_R32_SFLOAT;
  std::string error = create_image(*d_, depth, images_[static_cast<std::size_t>(depth_image_)]);
  if (!error.empty()) return "the depth texture: " + error;
  bool stencil = false;
  for (const PassInfo& pass : technique_->passes) stencil = stencil || (pass.stencil.enable && !pass.compute_shader);
  if (!stencil) return "";
  ImageShape buffer;
  buffer.width = width_, buffer.height = height_;
  buffer.format = stencil_format(*d_);
  buffer.stencil = true;
  if (buffer.format == VK_FORMAT_UNDEFINED) return "the device has no stencil format to draw with";
  error = create_image(*d_, buffer, images_[static_cast<std::size_t>(stencil_image_)]);
  return error.empty() ? "" : "the stencil buffer: " + error;
}

// The image a texture is, in a pass that starts with `back_buffer` holding the picture; -1 for none.
int Technique::image_of_texture(int texture, int back_buffer) const {
  if (texture < 0) return -1;
  const TextureInfo& t = model_->textures[static_cast<std::size_t>(texture)];
  if (t.semantic == TextureSemantic::kColor) return back_buffer_image_ + back_buffer;
  if (t.semantic == TextureSemantic::kDepth) return depth_image_;
  return texture;
}

VkImageView Technique::sampled_view(const SamplerInfo& sampler, int back_buffer) const {
  const Image& image = images_[static_cast<std::size_t>(image_of_texture(sampler.texture, back_buffer))];
  return sampler.srgb && image.srgb_view ? image.srgb_view : image.view;
}

std::string Technique::create_pool() {
  // A set per pass, each with at most every sampler and storage of the effect.
  const auto sets = static_cast<std::uint32_t>(technique_->passes.size());
  const auto samplers = sets * static_cast<std::uint32_t>(std::max<std::size_t>(1, model_->samplers.size()));
  const auto storages = sets * static_cast<std::uint32_t>(std::max<std::size_t>(1, model_->storages.size()));
  const VkDescriptorPoolSize sizes[3] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets}, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, samplers}, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, storages}};
  VkDescriptorPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  info.maxSets = std::max<std::uint32_t>(1, sets);
  info.poolSizeCount = 3;
  info.pPoolSizes = sizes;
  return d_->vkCreateDescriptorPool(d_->device, &info, nullptr, &pool_) == VK_SUCCESS ? "" : "vkCreateDescriptorPool failed";
}

std::string Technique::create_uniform_buffer() {
  if (block_.size == 0) return "";  // no uniforms, no block
  VkBufferCreateInfo buffer{};
  buffer.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  buffer.size = block_.size;
  buffer.usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (d_->vkCreateBuffer(d_->device, &buffer, nullptr, &uniform_buffer_) != VK_SUCCESS) return "vkCreateBuffer failed";
  VkMemoryRequirements needs;
  d_->vkGetBufferMemoryRequirements(d_->device, uniform_buffer_, &needs);
  uniform_memory_ = d_->allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!uniform_memory_ || d_->vkBindBufferMemory(d_->device, uniform_buffer_, uniform_memory_, 0) != VK_SUCCESS) return "no memory for the uniforms";
  return "";
}

std::string Technique::create_pass(std::size_t index, const GeneratedPass& generated) {
  Pass& pass = passes_[index];
  const PassInfo& info = technique_->passes[index];
  pass.info = &info;
  pass.compute = !generated.compute.empty();
  pass.writes_back_buffer = !pass.compute && info.render_target_count == 0;
  pass.copy_first = pass.writes_back_buffer && !covers_back_buffer(info, generated.may_discard);
  if (pass.writes_back_buffer) pass.targets.push_back(back_buffer_image_ + next_back_buffer(pass.back_buffer));
  for (int i = 0; !pass.compute && i < info.render_target_count; ++i) pass.targets.push_back(info.render_targets[i]);
  for (int unit : generated.sampler_units)
    pass.sampled.push_back(image_of_texture(model_->samplers[static_cast<std::size_t>(unit)].texture, pass.back_buffer));
  for (int unit : generated.image_units) pass.stored.push_back(model_->storages[static_cast<std::size_t>(unit)].texture);
  pass.sampler_units = generated.sampler_units;
  pass.image_units = generated.image_units;
  pass.may_discard = generated.may_discard;
  pass.live_code[0] = pass.compute ? generated.compute : generated.vertex;
  if (!pass.compute) pass.live_code[1] = generated.fragment;
  std::string error = create_bindings(pass, generated);
  if (error.empty()) error = create_draw(pass);
  return error.empty() ? "" : pass_label(info, index) + ": " + error;
}

std::string Technique::build_live(std::size_t index) {
  Pass& pass = passes_[index];
  if (pass.pipeline) return "";
  const SpirvStage stages[2] = {pass.compute ? SpirvStage::kCompute : SpirvStage::kVertex, SpirvStage::kFragment};
  for (int i = 0; i < (pass.compute ? 1 : 2); ++i) {
    if (pass.modules[i]) continue;
    const std::string log = create_shader_module(*d_, pass.live_code[i], stages[i], pass.modules[i]);
    if (!log.empty()) return pass_label(*pass.info, index) + ": glslang refused the generated code: " + log;
  }
  if (pass.compute) {
    pass.pipeline = create_compute_pipeline(*d_, pass.modules[0], pass.layout, cache_);
    return pass.pipeline ? "" : pass_label(*pass.info, index) + ": vkCreateComputePipelines failed";
  }
  pass.plan.vertex = pass.modules[0], pass.plan.fragment = pass.modules[1];
  pass.pipeline = create_graphics_pipeline(*d_, pass.plan, cache_);
  return pass.pipeline ? "" : pass_label(*pass.info, index) + ": vkCreateGraphicsPipelines failed";
}

std::string Technique::prepare(const UniformConstants* constants, std::size_t* built) {
  *built = 0;
  const Specialised* specialised = constants ? specialised_for(*constants) : nullptr;
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    if ((specialised && specialised->pipelines[i]) || passes_[i].pipeline) continue;
    const std::string error = build_live(i);
    if (!error.empty()) return error;
    ++*built;
  }
  return "";
}

std::string Technique::create_bindings(Pass& pass, const GeneratedPass& generated) {
  std::vector<VkDescriptorSetLayoutBinding> entries;
  if (block_.size) entries.push_back({static_cast<std::uint32_t>(kUniformBlockBinding), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_ALL, nullptr});
  for (std::size_t unit = 0; unit < generated.sampler_units.size(); ++unit)
    entries.push_back({static_cast<std::uint32_t>(kVulkanFirstSamplerBinding + static_cast<int>(unit)), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                       VK_SHADER_STAGE_ALL, nullptr});
  for (std::size_t unit = 0; unit < generated.image_units.size(); ++unit)
    entries.push_back({static_cast<std::uint32_t>(kVulkanFirstStorageBinding + static_cast<int>(unit)), VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1,
                       VK_SHADER_STAGE_ALL, nullptr});
  VkDescriptorSetLayoutCreateInfo layout{};
  layout.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  layout.bindingCount = static_cast<std::uint32_t>(entries.size());
  layout.pBindings = entries.data();
  if (d_->vkCreateDescriptorSetLayout(d_->device, &layout, nullptr, &pass.set_layout) != VK_SUCCESS) return "vkCreateDescriptorSetLayout failed";
  VkDescriptorSetAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocate.descriptorPool = pool_;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &pass.set_layout;
  if (d_->vkAllocateDescriptorSets(d_->device, &allocate, &pass.set) != VK_SUCCESS) return "vkAllocateDescriptorSets failed";
  VkPipelineLayoutCreateInfo pipeline_layout{};
  pipeline_layout.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pipeline_layout.setLayoutCount = 1;
  pipeline_layout.pSetLayouts = &pass.set_layout;
  if (d_->vkCreatePipelineLayout(d_->device, &pipeline_layout, nullptr, &pass.layout) != VK_SUCCESS) return "vkCreatePipelineLayout failed";

  // Descriptors: the uniform block, each sampler's view (in the general layout when the pass
  // also stores to the image), each storage's level.
  std::vector<VkDescriptorImageInfo> images(generated.sampler_units.size() + generated.image_units.size());
  std::vector<VkWriteDescriptorSet> writes;
  const VkDescriptorBufferInfo buffer{uniform_buffer_, 0, block_.size};
  auto write = [&](int binding, VkDescriptorType type, const VkDescriptorImageInfo* image) {
    VkWriteDescriptorSet w{};
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = pass.set;
    w.dstBinding = static_cast<std::uint32_t>(binding);
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pImageInfo = image;
    w.pBufferInfo = image ? nullptr : &buffer;
    writes.push_back(w);
  };
  if (block_.size) write(kUniformBlockBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, nullptr);
  for (std::size_t unit = 0; unit < generated.sampler_units.size(); ++unit) {
    const int sampler = generated.sampler_units[unit];
    const bool stored = contains(pass.stored, pass.sampled[unit]);
    images[unit] = {samplers_[static_cast<std::size_t>(sampler)], sampled_view(model_->samplers[static_cast<std::size_t>(sampler)], pass.back_buffer),
                    stored ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write(kVulkanFirstSamplerBinding + static_cast<int>(unit), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, &images[unit]);
  }
  for (std::size_t unit = 0; unit < generated.image_units.size(); ++unit) {
    const StorageInfo& s = model_->storages[static_cast<std::size_t>(generated.image_units[unit])];
    const Image& image = images_[static_cast<std::size_t>(s.texture)];
    pass.owned_views.push_back(level_view(*d_, image, s.mip_level, image.format));
    if (!pass.owned_views.back()) return "vkCreateImageView failed for storage '" + s.name + "'";
    VkDescriptorImageInfo& info = images[generated.sampler_units.size() + unit];
    info = {VK_NULL_HANDLE, pass.owned_views.back(), VK_IMAGE_LAYOUT_GENERAL};
    write(kVulkanFirstStorageBinding + static_cast<int>(unit), VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, &info);
  }
  d_->vkUpdateDescriptorSets(d_->device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return "";
}

// A graphics pass's render pass, framebuffer and the plan its pipelines are made from.
std::string Technique::create_draw(Pass& pass) {
  if (pass.compute) return "";
  GraphicsPlan plan;
  plan.pass = pass.info;
  plan.layout = pass.layout;
  std::vector<VkImageView> views;
  for (std::size_t i = 0; i < pass.targets.size(); ++i) {
    const Image& image = images_[static_cast<std::size_t>(pass.targets[i])];
    const bool srgb = pass.info->srgb_write && image.srgb_view;
    // An attachment is one level: level 0 of a texture with mips.
    VkImageView view = srgb ? image.srgb_view : image.view;
    if (image.levels > 1) {
      pass.owned_views.push_back(level_view(*d_, image, 0, srgb ? image.srgb_format : image.format));
      view = pass.owned_views.back();
      if (!view) return "vkCreateImageView failed for a render target";
    }
    views.push_back(view);
    plan.attachments.push_back({srgb ? image.srgb_format : image.format, image.integer});
    if (i == 0) plan.viewport_width = plan.area_width = image.width, plan.viewport_height = plan.area_height = image.height;
    plan.area_width = std::min(plan.area_width, image.width);
    plan.area_height = std::min(plan.area_height, image.height);
  }
  // The stencil test applies where the first target has the frame's size, as in ReShade.
  const Image& stencil = images_[static_cast<std::size_t>(stencil_image_)];
  pass.stencil = plan.stencil = pass.info->stencil.enable && stencil.image && plan.viewport_width == width_ && plan.viewport_height == height_;
  if (pass.stencil) views.push_back(stencil.view);
  pass.area_width = plan.area_width, pass.area_height = plan.area_height;
  pass.render_pass = plan.render_pass =
      create_render_pass(*d_, plan.attachments, pass.info->clear_render_targets, pass.stencil ? stencil.format : VK_FORMAT_UNDEFINED);
  if (!pass.render_pass) return "vkCreateRenderPass failed";
  VkFramebufferCreateInfo framebuffer{};
  framebuffer.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  framebuffer.renderPass = pass.render_pass;
  framebuffer.attachmentCount = static_cast<std::uint32_t>(views.size());
  framebuffer.pAttachments = views.data();
  framebuffer.width = static_cast<std::uint32_t>(plan.area_width);
  framebuffer.height = static_cast<std::uint32_t>(plan.area_height);
  framebuffer.layers = 1;
  if (d_->vkCreateFramebuffer(d_->device, &framebuffer, nullptr, &pass.framebuffer) != VK_SUCCESS) return "vkCreateFramebuffer failed";
  pass.plan = plan;
  return "";
}

void Technique::destroy() {
  if (!d_) return;
  const Device& d = *d_;
  for (Specialised& set : specialised_) destroy(set);
  specialised_.clear();
  for (Pass& pass : passes_) {
    if (pass.pipeline) d.vkDestroyPipeline(d.device, pass.pipeline, nullptr);
    if (pass.framebuffer) d.vkDestroyFramebuffer(d.device, pass.framebuffer, nullptr);
    if (pass.render_pass) d.vkDestroyRenderPass(d.device, pass.render_pass, nullptr);
    if (pass.layout) d.vkDestroyPipelineLayout(d.device, pass.layout, nullptr);
    if (pass.set_layout) d.vkDestroyDescriptorSetLayout(d.device, pass.set_layout, nullptr);
    for (VkShaderModule m : pass.modules)
      if (m) d.vkDestroyShaderModule(d.device, m, nullptr);
    for (VkImageView v : pass.owned_views)
      if (v) d.vkDestroyImageView(d.device, v, nullptr);
  }
  passes_.clear();
  if (pool_) d.vkDestroyDescriptorPool(d.device, pool_, nullptr);  // frees the sets
  pool_ = VK_NULL_HANDLE;
  if (uniform_buffer_) d.vkDestroyBuffer(d.device, uniform_buffer_, nullptr);
  if (uniform_memory_) d.vkFreeMemory(d.device, uniform_memory_, nullptr);
  uniform_buffer_ = VK_NULL_HANDLE, uniform_memory_ = VK_NULL_HANDLE;
  for (VkSampler s : samplers_)
    if (s) d.vkDestroySampler(d.device, s, nullptr);
  samplers_.clear();
  frame_alpha_.destroy(d);
  uploads_.destroy();
  for (Image& image : images_) destroy_image(d, image);
  images_.clear();
  started_ = false;
  d_ = nullptr;
}

}  // namespace pfx::fx::vulkan
