// Runs an FX conformance file of one pass into the back buffer (uniforms, and the back buffer as
// its only texture) through its SPIR-V on a Vulkan device, headless, and judges the picture as
// run_conformance.py does: `checks`, every pixel green, or the checks whose columns are not
// (check i is the columns [i * CELL, (i + 1) * CELL)); `input`, the back buffer's bytes (a
// gradient with a varying alpha, made here); `invert`, 255 minus them in R, G and B. What the GL
// runtime and the conformance suite hold the GLSL to, this holds the Vulkan dialect's SPIR-V to,
// on the device Vulkan gives (lavapipe in the tests).
//
// usage: fx_vulkan_checks [-IFOLDER...] --size WxH [--cell N] [--expect checks|input|invert] FILE.fx
// Exit status: 0 every check holds, 1 some fail or Vulkan fails, 3 the file needs more than this
// runs (it says what), 2 usage.
#include <dlfcn.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "codegen/glsl_generator.hpp"
#include "codegen/spirv_module.hpp"
#include "front_end.hpp"

namespace {

#define VK_OK(call)                                                                \
  do {                                                                             \
    VkResult result_ = (call);                                                     \
    if (result_ != VK_SUCCESS) {                                                   \
      std::fprintf(stderr, "FAIL: %s returned %d\n", #call, static_cast<int>(result_)); \
      std::exit(1);                                                                \
    }                                                                              \
  } while (0)

// A Vulkan structure of `type`, every other member zero.
template <typename T>
T vk(VkStructureType type) {
  T out{};
  out.sType = type;
  return out;
}

using pfx::fx::BaseType;
using pfx::fx::Type;

// The uniform block's bytes: each live uniform at its std140 offset, in the order the generator
// declares them (model order), with its initial value.
std::vector<unsigned char> uniform_block(const pfx::fx::EffectModel& model, const pfx::fx::GeneratedPass& pass) {
  std::vector<unsigned char> bytes;
  std::size_t offset = 0;
  auto put = [&](std::size_t at, BaseType base, double value) {
    if (bytes.size() < at + 4) bytes.resize(at + 4, 0);
    std::uint32_t bits;
    if (base == BaseType::kInt) bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(value));
    else if (base == BaseType::kUint) bits = static_cast<std::uint32_t>(static_cast<long long>(value));
    else if (base == BaseType::kBool) bits = value != 0 ? 1u : 0u;
    else {
      float f = static_cast<float>(value);
      std::memcpy(&bits, &f, 4);
    }
    std::memcpy(bytes.data() + at, &bits, 4);
  };
  for (int index : pass.uniforms) {
    const pfx::fx::UniformInfo& u = model.uniforms[static_cast<std::size_t>(index)];
    const Type& t = u.type;
    const BaseType base = t.is_floating() ? BaseType::kFloat : t.base;
    std::size_t elements = 1;
    for (int size : t.array) elements *= static_cast<std::size_t>(size);
    const int rows = t.is_matrix() ? t.rows : 1, per_row = t.is_matrix() ? t.columns : t.components();
    const bool slots = t.is_array() || t.is_matrix();  // each element (matrix row) in a 16-byte slot
    const std::size_t align = slots || per_row > 2 ? 16 : per_row == 2 ? 8 : 4;
    offset = (offset + align - 1) / align * align;
    std::size_t next = 0;
    for (std::size_t e = 0; e < elements; ++e)
      for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < per_row; ++c) put(offset + static_cast<std::size_t>(c) * 4, base, next < u.initial.size() ? u.initial[next] : 0.0), ++next;
        offset += slots ? 16 : static_cast<std::size_t>(per_row) * 4;
      }
  }
  bytes.resize((bytes.size() + 15) / 16 * 16);
  return bytes;
}

struct Device {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  VkPhysicalDeviceMemoryProperties memory{};

  Device() {
    // lavapipe stays mapped to the end: the loader unloads the driver at vkDestroyInstance, and a
    // block it keeps in its globals would then read as a leak of an unknown module under
    // LeakSanitizer (docs/reliability.md). Another driver is not touched.
    (void)dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
    auto app = vk<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "fx_vulkan_checks";
    app.apiVersion = VK_API_VERSION_1_0;
    auto info = vk<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;
    VK_OK(vkCreateInstance(&info, nullptr, &instance));
    std::uint32_t count = 1;
    VkResult listed = vkEnumeratePhysicalDevices(instance, &count, &physical);
    if ((listed != VK_SUCCESS && listed != VK_INCOMPLETE) || count == 0) {
      std::fprintf(stderr, "FAIL: no Vulkan device (install mesa-vulkan-drivers for lavapipe)\n");
      std::exit(1);
    }
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> properties(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, properties.data());
    while (family < families && !(properties[family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) ++family;
    float priority = 1.0f;
    auto queue_info = vk<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    auto device_info = vk<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    VK_OK(vkCreateDevice(physical, &device_info, nullptr, &device));
    vkGetDeviceQueue(device, family, 0, &queue);
  }
  ~Device() {
    vkDestroyDevice(device, nullptr);
    vkDestroyInstance(instance, nullptr);
  }

  VkDeviceMemory allocate(VkMemoryRequirements needs, VkMemoryPropertyFlags flags) const {
    auto info = vk<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    info.allocationSize = needs.size;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((needs.memoryTypeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
        info.memoryTypeIndex = i;
        break;
      }
    VkDeviceMemory out;
    VK_OK(vkAllocateMemory(device, &info, nullptr, &out));
    return out;
  }

  // A host-visible buffer holding `size` bytes (`data` copied in when given).
  VkBuffer buffer(VkDeviceSize size, VkBufferUsageFlags usage, VkDeviceMemory& memory_out, const void* data) const {
    auto info = vk<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    info.usage = usage;
    VkBuffer out;
    VK_OK(vkCreateBuffer(device, &info, nullptr, &out));
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(device, out, &needs);
    memory_out = allocate(needs, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VK_OK(vkBindBufferMemory(device, out, memory_out, 0));
    if (data) {
      void* mapped;
      VK_OK(vkMapMemory(device, memory_out, 0, size, 0, &mapped));
      std::memcpy(mapped, data, static_cast<std::size_t>(size));
      vkUnmapMemory(device, memory_out);
    }
    return out;
  }

  VkShaderModule module(const std::vector<std::uint32_t>& words) const {
    auto info = vk<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = words.size() * 4;
    info.pCode = words.data();
    VkShaderModule out;
    VK_OK(vkCreateShaderModule(device, &info, nullptr, &out));
    return out;
  }
};

bool spirv(const std::string& glsl, pfx::fx::SpirvStage stage, std::vector<std::uint32_t>& words) {
  std::string log;
  if (pfx::fx::compile_spirv(glsl, stage, words, log)) return true;
  std::printf("FAIL: glslang refused the Vulkan GLSL:\n%s\n%s\n", log.c_str(), glsl.c_str());
  return false;
}

}  // namespace

struct Judged {
  std::string expect;  // checks, input or invert
  int width, height, cell;
};
int run(const pfx::fx::EffectModel& model, const pfx::fx::GeneratedPass& pass, const Judged& judged);

int main(int argc, char** argv) {
  pfx::fx::FrontEndOptions options;
  std::string file;
  int width = 0, height = 0, cell = 4;
  std::string expect = "checks";
  for (int i = 1; i < argc; ++i) {
    std::string argument = argv[i];
    if (argument.rfind("-I", 0) == 0) options.preprocessor.include_folders.push_back(argument.substr(2));
    else if (argument == "--size" && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
    else if (argument == "--cell" && i + 1 < argc) cell = std::atoi(argv[++i]);
    else if (argument == "--expect" && i + 1 < argc) expect = argv[++i];
    else file = argument;
  }
  if (file.empty() || width <= 0 || height <= 0 || cell <= 0 || (expect != "checks" && expect != "input" && expect != "invert")) {
    std::fprintf(stderr, "usage: fx_vulkan_checks [-IFOLDER...] --size WxH [--cell N] [--expect checks|input|invert] FILE.fx\n");
    return 2;
  }
  options.preprocessor.buffer_width = width;
  options.preprocessor.buffer_height = height;
  auto result = pfx::fx::compile_front_end(file, options);
  pfx::fx::EffectModel model;
  if (result->ok()) model = pfx::fx::build_effect_model(result->unit, result->diagnostics);
  if (!result->ok()) return std::printf("FAIL: %s", result->diagnostics.format_all().c_str()), 1;
  if (model.techniques.size() != 1 || model.techniques[0].passes.size() != 1)
    return std::printf("not run: %s has more than one technique or pass\n", file.c_str()), 3;
  const pfx::fx::PassInfo& info = model.techniques[0].passes[0];
  if (info.compute_shader || info.render_target_count > 0 || info.blend[0].enable || info.stencil.enable)
    return std::printf("not run: the pass computes, renders to textures, blends or uses stencil\n"), 3;
  pfx::fx::GeneratedPass pass = pfx::fx::generate_pass(result->unit, model, info, result->diagnostics, nullptr, pfx::fx::GlslDialect::kVulkan);
  if (result->diagnostics.has_errors()) return std::printf("FAIL: %s", result->diagnostics.format_all().c_str()), 1;
  if (!pass.image_units.empty()) return std::printf("not run: the pass uses storages\n"), 3;
  for (int unit : pass.sampler_units) {
    const int texture = model.samplers[static_cast<std::size_t>(unit)].texture;
    if (texture < 0 || model.textures[static_cast<std::size_t>(texture)].semantic != pfx::fx::TextureSemantic::kColor)
      return std::printf("not run: the pass samples a texture other than the back buffer\n"), 3;
  }
  for (int u : pass.uniforms)
    if (!model.uniforms[static_cast<std::size_t>(u)].source.empty())
      return std::printf("not run: the uniform '%s' has a source\n", model.uniforms[static_cast<std::size_t>(u)].name.c_str()), 3;
  return run(model, pass, Judged{expect, width, height, cell});
}

namespace {

// The render pass, framebuffer and pipeline of one pass into a `width` x `height` RGBA8 image.
struct Target {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;

  Target(const Device& d, int width, int height) {
    auto image_info = vk<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    image_info.imageType = VK_IMAGE_TYPE_2D;
    image_info.format = VK_FORMAT_R8G8B8A8_UNORM;
    image_info.extent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
    image_info.mipLevels = image_info.arrayLayers = 1;
    image_info.samples = VK_SAMPLE_COUNT_1_BIT;
    image_info.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VK_OK(vkCreateImage(d.device, &image_info, nullptr, &image));
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(d.device, image, &needs);
    memory = d.allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_OK(vkBindImageMemory(d.device, image, memory, 0));
    auto view_info = vk<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view_info.image = image;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = image_info.format;
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VK_OK(vkCreateImageView(d.device, &view_info, nullptr, &view));
    VkAttachmentDescription attachment{};
    attachment.format = image_info.format;
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachment.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;
    auto pass_info = vk<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    pass_info.attachmentCount = 1;
    pass_info.pAttachments = &attachment;
    pass_info.subpassCount = 1;
    pass_info.pSubpasses = &subpass;
    VK_OK(vkCreateRenderPass(d.device, &pass_info, nullptr, &render_pass));
    auto framebuffer_info = vk<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    framebuffer_info.renderPass = render_pass;
    framebuffer_info.attachmentCount = 1;
    framebuffer_info.pAttachments = &view;
    framebuffer_info.width = image_info.extent.width;
    framebuffer_info.height = image_info.extent.height;
    framebuffer_info.layers = 1;
    VK_OK(vkCreateFramebuffer(d.device, &framebuffer_info, nullptr, &framebuffer));
  }
  void destroy(const Device& d) {
    vkDestroyFramebuffer(d.device, framebuffer, nullptr);
    vkDestroyRenderPass(d.device, render_pass, nullptr);
    vkDestroyImageView(d.device, view, nullptr);
    vkDestroyImage(d.device, image, nullptr);
    vkFreeMemory(d.device, memory, nullptr);
  }
};

VkPipeline pipeline(const Device& d, const Target& target, VkPipelineLayout layout, VkShaderModule vertex, VkShaderModule fragment,
                    int width, int height) {
  VkPipelineShaderStageCreateInfo stages[2] = {vk<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO),
                                                vk<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO)};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment;
  stages[1].pName = "main";
  auto input = vk<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  auto assembly = vk<VkPipelineInputAssemblyStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0, 0, static_cast<float>(width), static_cast<float>(height), 0, 1};
  VkRect2D scissor{{0, 0}, {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)}};
  auto viewport_state = vk<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewport_state.viewportCount = viewport_state.scissorCount = 1;
  viewport_state.pViewports = &viewport;
  viewport_state.pScissors = &scissor;
  auto raster = vk<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1;
  auto multisample = vk<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  auto blend_state = vk<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend_state.attachmentCount = 1;
  blend_state.pAttachments = &blend;
  auto info = vk<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport_state;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blend_state;
  info.layout = layout;
  info.renderPass = target.render_pass;
  VkPipeline out;
  VK_OK(vkCreateGraphicsPipelines(d.device, VK_NULL_HANDLE, 1, &info, nullptr, &out));
  return out;
}

// The checks whose columns hold a pixel that is not pure green.
std::vector<int> failed_checks(const unsigned char* rgba, int width, int height, int cell) {
  std::vector<int> failed;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = rgba + (static_cast<std::size_t>(y) * width + x) * 4;
      if (p[0] == 0 && p[1] == 255 && p[2] == 0) continue;
      if (failed.empty() || failed.back() != x / cell) failed.push_back(x / cell);
    }
  std::sort(failed.begin(), failed.end());
  failed.erase(std::unique(failed.begin(), failed.end()), failed.end());
  return failed;
}

}  // namespace


namespace {

// The back buffer the pass reads: R across, G down, B from both, alpha varying, so that a picture
// upside down, mirrored or shifted by a texel cannot pass for it.
std::vector<unsigned char> gradient(int width, int height) {
  std::vector<unsigned char> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      unsigned char* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      p[0] = static_cast<unsigned char>(x * 255 / std::max(1, width - 1));
      p[1] = static_cast<unsigned char>(y * 255 / std::max(1, height - 1));
      p[2] = static_cast<unsigned char>((x * 37 + y * 11) & 255);
      p[3] = static_cast<unsigned char>((x * 7 + y * 13 + 1) & 255);
    }
  return rgba;
}

void barrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags before, VkAccessFlags after,
             VkPipelineStageFlags source, VkPipelineStageFlags destination) {
  auto b = vk<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
  b.srcAccessMask = before;
  b.dstAccessMask = after;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(commands, source, destination, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The back buffer as a sampled RGBA8 image, with a UNORM view and an sRGB one (SRGBTexture).
struct BackBuffer {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE, staging_memory = VK_NULL_HANDLE;
  VkImageView unorm = VK_NULL_HANDLE, srgb = VK_NULL_HANDLE;
  VkBuffer staging = VK_NULL_HANDLE;
  int width, height;

  BackBuffer(const Device& d, const std::vector<unsigned char>& rgba, int w, int h) : width(w), height(h) {
    auto info = vk<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    VK_OK(vkCreateImage(d.device, &info, nullptr, &image));
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(d.device, image, &needs);
    memory = d.allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_OK(vkBindImageMemory(d.device, image, memory, 0));
    unorm = view(d, VK_FORMAT_R8G8B8A8_UNORM);
    srgb = view(d, VK_FORMAT_R8G8B8A8_SRGB);
    staging = d.buffer(rgba.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging_memory, rgba.data());
  }
  VkImageView view(const Device& d, VkFormat format) const {
    auto info = vk<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView out;
    VK_OK(vkCreateImageView(d.device, &info, nullptr, &out));
    return out;
  }
  // The pixels into the image, top row first (Vulkan's and FX's order), ready to sample.
  void record_upload(VkCommandBuffer commands) const {
    barrier(commands, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
    vkCmdCopyBufferToImage(commands, staging, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    barrier(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  }
  void destroy(const Device& d) {
    vkDestroyImageView(d.device, unorm, nullptr);
    vkDestroyImageView(d.device, srgb, nullptr);
    vkDestroyImage(d.device, image, nullptr);
    vkFreeMemory(d.device, memory, nullptr);
    vkDestroyBuffer(d.device, staging, nullptr);
    vkFreeMemory(d.device, staging_memory, nullptr);
  }
};

VkSamplerAddressMode address(pfx::fx::AddressMode mode) {
  switch (mode) {
    case pfx::fx::AddressMode::kMirror: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case pfx::fx::AddressMode::kWrap: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case pfx::fx::AddressMode::kBorder: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    case pfx::fx::AddressMode::kClamp: break;
  }
  return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
}

VkSampler sampler(const Device& d, const pfx::fx::SamplerInfo& s) {
  auto info = vk<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  info.magFilter = s.mag_filter == pfx::fx::FilterMode::kPoint ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  info.minFilter = s.min_filter == pfx::fx::FilterMode::kPoint ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  info.mipmapMode = s.mip_filter == pfx::fx::FilterMode::kPoint ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = address(s.address[0]);
  info.addressModeV = address(s.address[1]);
  info.addressModeW = address(s.address[2]);
  info.mipLodBias = s.lod_bias;
  info.minLod = s.min_lod;
  info.maxLod = s.max_lod;
  info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  VkSampler out;
  VK_OK(vkCreateSampler(d.device, &info, nullptr, &out));
  return out;
}

// The pass's descriptor set: the uniform block at its binding, each sampler at the binding after
// the first sampler binding that its unit gives.
struct Bindings {
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VkBuffer uniforms = VK_NULL_HANDLE;
  VkDeviceMemory uniform_memory = VK_NULL_HANDLE;
  std::vector<VkSampler> samplers;

  Bindings(const Device& d, const pfx::fx::EffectModel& model, const pfx::fx::GeneratedPass& pass, const BackBuffer& back_buffer) {
    const std::vector<unsigned char> block = uniform_block(model, pass);
    std::vector<VkDescriptorSetLayoutBinding> entries;
    if (!block.empty())
      entries.push_back({static_cast<std::uint32_t>(pfx::fx::kVulkanUniformBinding), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    for (std::size_t unit = 0; unit < pass.sampler_units.size(); ++unit)
      entries.push_back({static_cast<std::uint32_t>(pfx::fx::kVulkanFirstSamplerBinding + unit), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    auto layout_info = vk<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    layout_info.bindingCount = static_cast<std::uint32_t>(entries.size());
    layout_info.pBindings = entries.data();
    VK_OK(vkCreateDescriptorSetLayout(d.device, &layout_info, nullptr, &layout));
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16}};
    auto pool_info = vk<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 2;
    pool_info.pPoolSizes = sizes;
    VK_OK(vkCreateDescriptorPool(d.device, &pool_info, nullptr, &pool));
    auto allocate = vk<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &layout;
    VK_OK(vkAllocateDescriptorSets(d.device, &allocate, &set));
    std::vector<VkWriteDescriptorSet> writes;
    VkDescriptorBufferInfo buffer_info{};
    std::vector<VkDescriptorImageInfo> images(pass.sampler_units.size());
    if (!block.empty()) {
      uniforms = d.buffer(block.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, uniform_memory, block.data());
      buffer_info = {uniforms, 0, block.size()};
      auto write = vk<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      write.dstSet = set;
      write.dstBinding = static_cast<std::uint32_t>(pfx::fx::kVulkanUniformBinding);
      write.descriptorCount = 1;
      write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      write.pBufferInfo = &buffer_info;
      writes.push_back(write);
    }
    for (std::size_t unit = 0; unit < pass.sampler_units.size(); ++unit) {
      const pfx::fx::SamplerInfo& info = model.samplers[static_cast<std::size_t>(pass.sampler_units[unit])];
      samplers.push_back(sampler(d, info));
      images[unit] = {samplers.back(), info.srgb ? back_buffer.srgb : back_buffer.unorm, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
      auto write = vk<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      write.dstSet = set;
      write.dstBinding = static_cast<std::uint32_t>(pfx::fx::kVulkanFirstSamplerBinding + unit);
      write.descriptorCount = 1;
      write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      write.pImageInfo = &images[unit];
      writes.push_back(write);
    }
    vkUpdateDescriptorSets(d.device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }
  void destroy(const Device& d) {
    for (VkSampler s : samplers) vkDestroySampler(d.device, s, nullptr);
    if (uniforms) vkDestroyBuffer(d.device, uniforms, nullptr);
    if (uniform_memory) vkFreeMemory(d.device, uniform_memory, nullptr);
    vkDestroyDescriptorPool(d.device, pool, nullptr);
    vkDestroyDescriptorSetLayout(d.device, layout, nullptr);
  }
};

// What the picture should be, said as the conformance runner says it; "" when it is.
std::string judge(const Judged& judged, const unsigned char* out, const std::vector<unsigned char>& in) {
  if (judged.expect == "checks") {
    const std::vector<int> failed = failed_checks(out, judged.width, judged.height, judged.cell);
    std::string list;
    for (int check : failed) list += (list.empty() ? "" : ", ") + std::to_string(check);
    return failed.empty() ? "" : "checks [" + list + "] of " + std::to_string((judged.width + judged.cell - 1) / judged.cell);
  }
  const bool invert = judged.expect == "invert";
  for (std::size_t i = 0; i < in.size(); ++i) {
    const bool alpha = i % 4 == 3;
    if (invert && alpha) continue;
    const int wanted = invert ? 255 - in[i] : in[i];
    if (out[i] != wanted) {
      const std::size_t pixel = i / 4;
      return "pixel (" + std::to_string(pixel % static_cast<std::size_t>(judged.width)) + ", " +
             std::to_string(pixel / static_cast<std::size_t>(judged.width)) + ") channel " + std::to_string(i % 4) + " is " +
             std::to_string(out[i]) + ", not " + std::to_string(wanted) + (invert ? " (255 - the input)" : " (the input)");
    }
  }
  return "";
}

}  // namespace

int run(const pfx::fx::EffectModel& model, const pfx::fx::GeneratedPass& pass, const Judged& judged) {
  std::vector<std::uint32_t> vertex_words, fragment_words;
  if (!spirv(pass.vertex, pfx::fx::SpirvStage::kVertex, vertex_words) || !spirv(pass.fragment, pfx::fx::SpirvStage::kFragment, fragment_words))
    return 1;
  const int width = judged.width, height = judged.height;
  const std::vector<unsigned char> input = gradient(width, height);
  Device d;
  Target target(d, width, height);
  BackBuffer back_buffer(d, input, width, height);
  Bindings bindings(d, model, pass, back_buffer);
  auto layout_info = vk<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &bindings.layout;
  VkPipelineLayout layout;
  VK_OK(vkCreatePipelineLayout(d.device, &layout_info, nullptr, &layout));
  VkShaderModule vertex = d.module(vertex_words), fragment = d.module(fragment_words);
  VkPipeline graphics = pipeline(d, target, layout, vertex, fragment, width, height);
  const VkDeviceSize pixels_size = static_cast<VkDeviceSize>(width) * height * 4;
  VkDeviceMemory readback_memory;
  VkBuffer readback = d.buffer(pixels_size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, readback_memory, nullptr);

  // Upload the back buffer, draw the pass, copy the picture out; submit and wait.
  auto pool_info = vk<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool_info.queueFamilyIndex = d.family;
  VkCommandPool command_pool;
  VK_OK(vkCreateCommandPool(d.device, &pool_info, nullptr, &command_pool));
  auto command_info = vk<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  command_info.commandPool = command_pool;
  command_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  command_info.commandBufferCount = 1;
  VkCommandBuffer commands;
  VK_OK(vkAllocateCommandBuffers(d.device, &command_info, &commands));
  auto begin = vk<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  VK_OK(vkBeginCommandBuffer(commands, &begin));
  back_buffer.record_upload(commands);
  VkClearValue clear{};
  auto pass_begin = vk<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
  pass_begin.renderPass = target.render_pass;
  pass_begin.framebuffer = target.framebuffer;
  pass_begin.renderArea = {{0, 0}, {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)}};
  pass_begin.clearValueCount = 1;
  pass_begin.pClearValues = &clear;
  vkCmdBeginRenderPass(commands, &pass_begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, graphics);
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &bindings.set, 0, nullptr);
  vkCmdDraw(commands, static_cast<std::uint32_t>(model.techniques[0].passes[0].vertex_count), 1, 0, 0);
  vkCmdEndRenderPass(commands);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
  vkCmdCopyImageToBuffer(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &region);
  VK_OK(vkEndCommandBuffer(commands));
  auto submit = vk<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  VK_OK(vkQueueSubmit(d.queue, 1, &submit, VK_NULL_HANDLE));
  VK_OK(vkQueueWaitIdle(d.queue));

  void* mapped;
  VK_OK(vkMapMemory(d.device, readback_memory, 0, pixels_size, 0, &mapped));
  const std::string wrong = judge(judged, static_cast<const unsigned char*>(mapped), input);
  vkUnmapMemory(d.device, readback_memory);

  vkDestroyCommandPool(d.device, command_pool, nullptr);
  vkDestroyBuffer(d.device, readback, nullptr);
  vkFreeMemory(d.device, readback_memory, nullptr);
  vkDestroyPipeline(d.device, graphics, nullptr);
  vkDestroyShaderModule(d.device, vertex, nullptr);
  vkDestroyShaderModule(d.device, fragment, nullptr);
  vkDestroyPipelineLayout(d.device, layout, nullptr);
  bindings.destroy(d);
  back_buffer.destroy(d);
  target.destroy(d);
  if (!wrong.empty()) return std::printf("FAIL: %s\n", wrong.c_str()), 1;
  if (judged.expect == "checks") return std::printf("ok: %d checks\n", (width + judged.cell - 1) / judged.cell), 0;
  return std::printf("ok: the picture is %s\n", judged.expect == "input" ? "the input" : "the input inverted"), 0;
}
