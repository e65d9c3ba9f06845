#include "vk_transport.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

#include "vk_memory.hpp"

namespace pfx::vk {
namespace {

constexpr VkFormat kEightBitFormats[] = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM,
                                          VK_FORMAT_B8G8R8A8_SRGB};

bool is_srgb(VkFormat format) { return format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB; }

Between blitted(VkFormat format) {
  Between between;
  between.blits = true;
  between.srgb = is_srgb(format);
  return between;
}

VkFormat between_format(Between between) {
  // Raw texels of either width are 32 bits each; the format only has to let a copy take them.
  return between.blits && between.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

}  // namespace

bool is_eight_bit(VkFormat format) {
  return std::find(std::begin(kEightBitFormats), std::end(kEightBitFormats), format) != std::end(kEightBitFormats);
}

bool is_ten_bit(VkFormat format) {
  return format == VK_FORMAT_A2B10G10R10_UNORM_PACK32 || format == VK_FORMAT_A2R10G10B10_UNORM_PACK32;
}

bool Transport::can_blit(VkFormat format) const {
  VkFormatProperties properties{};
  f_.GetPhysicalDeviceFormatProperties(physical_device_, format, &properties);
  const VkFormatFeatureFlags both = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
  return (properties.optimalTilingFeatures & both) == both;
}

Between Transport::between_for(Path path, VkFormat format) const {
  const bool blits =
      path == Path::SHARED && std::find(blit_formats_.begin(), blit_formats_.end(), format) != blit_formats_.end();
  if (blits) return blitted(format);
  Between between;
  between.ten_bit = is_ten_bit(format);
  return between;
}

Transport::~Transport() {
  wait_idle();
  release_between();
  if (in_done_) f_.DestroyFence(device_, in_done_, nullptr);
  if (out_done_) f_.DestroyFence(device_, out_done_, nullptr);
  if (pool_) f_.DestroyCommandPool(device_, pool_, nullptr);  // frees its command buffers
}

bool Transport::init(uint32_t queue_family_index, SetLoaderData set_loader_data, std::string* error) {
  VkCommandBuffer buffers[2] = {};
  if (!make_command_buffers(f_, device_, queue_family_index, set_loader_data, 2, &pool_, buffers, error)) return false;
  in_ = buffers[0];
  out_ = buffers[1];
  VkFenceCreateInfo fence_info{};
  fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkResult result = f_.CreateFence(device_, &fence_info, nullptr, &in_done_);
  if (result == VK_SUCCESS) result = f_.CreateFence(device_, &fence_info, nullptr, &out_done_);
  if (result != VK_SUCCESS) *error = "could not make the bridge's fences: " + result_name(result);
  // Once: which 8-bit formats the device can blit to and from their go-between's.
  for (VkFormat format : kEightBitFormats)
    if (can_blit(format) && can_blit(between_format(blitted(format)))) blit_formats_.push_back(format);
  return result == VK_SUCCESS;
}

void Transport::wait_idle() {
  if (!out_pending_) return;
  f_.WaitForFences(device_, 1, &out_done_, VK_TRUE, UINT64_MAX);
  f_.ResetFences(device_, 1, &out_done_);
  out_pending_ = false;
}

void Transport::release_between() {
  if (mapped_) f_.UnmapMemory(device_, memory_);
  if (between_image_) f_.DestroyImage(device_, between_image_, nullptr);
  if (between_buffer_) f_.DestroyBuffer(device_, between_buffer_, nullptr);
  if (memory_) f_.FreeMemory(device_, memory_, nullptr);
  mapped_ = nullptr;
  between_image_ = VK_NULL_HANDLE;
  between_buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  width_ = height_ = 0;
}

bool Transport::prepared(Path path, uint32_t width, uint32_t height, Between between) const {
  return memory_ && path_ == path && width_ == width && height_ == height && between_ == between;
}

bool Transport::make_shared_image(std::string* error) {
  VkExternalMemoryImageCreateInfo external{};
  external.sType = VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_IMAGE_CREATE_INFO;
  external.handleTypes = VK_EXTERNAL_MEMORY_HANDLE_TYPE_OPAQUE_FD_BIT;
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.pNext = &external;
  // The GL views the bits as RGBA8 and as SRGB8_ALPHA8 both.
  info.flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = between_format(between_);
  info.extent = {width_, height_, 1};
  info.mipLevels = 1;
  info.arrayLayers = between_.blits ? 2 : 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  // What the GL does with it too: samples it and renders into it.
  info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkResult result = f_.CreateImage(device_, &info, nullptr, &between_image_);
  if (result != VK_SUCCESS) {
    *error = "could not make an exportable image: " + result_name(result);
    return false;
  }
  VkMemoryRequirements needs{};
  f_.GetImageMemoryRequirements(device_, between_image_, &needs);
  VkExportMemoryAllocateInfo export_info{};
  export_info.sType = VK_STRUCTURE_TYPE_EXPORT_MEMORY_ALLOCATE_INFO;
  export_info.handleTypes = VK_EXTERNAL_MEMORY_HANDLE_TYPE_OPAQUE_FD_BIT;
  if (!allocate_memory(f_, device_, physical_device_, needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &export_info, &memory_, error) &&
      !allocate_memory(f_, device_, physical_device_, needs, 0, &export_info, &memory_, error))
    return false;
  result = f_.BindImageMemory(device_, between_image_, memory_, 0);
  if (result != VK_SUCCESS) {
    *error = "could not bind the exportable image's memory: " + result_name(result);
    return false;
  }
  between_fresh_ = true;
  return true;
}

bool Transport::make_host_buffer(std::string* error) {
  HostBuffer made;
  if (!pfx::vk::make_host_buffer(f_, device_, physical_device_, row_bytes() * height_, &made, error)) return false;
  between_buffer_ = made.buffer;
  memory_ = made.memory;
  mapped_ = made.mapped;
  return true;
}

bool Transport::prepare(Path path, uint32_t width, uint32_t height, Between between, int* fd,
                        uint64_t* memory_size, std::string* error) {
  *fd = -1;  // the go-between the GL side already has serves
  if (prepared(path, width, height, between)) return true;
  wait_idle();
  release_between();
  path_ = path;
  width_ = width;
  height_ = height;
  between_ = between;
  const bool made = path == Path::SHARED ? make_shared_image(error) : make_host_buffer(error);
  if (!made) {
    release_between();
    return false;
  }
  if (path == Path::HOST) return true;
  VkMemoryGetFdInfoKHR fd_info{};
  fd_info.sType = VK_STRUCTURE_TYPE_MEMORY_GET_FD_INFO_KHR;
  fd_info.memory = memory_;
  fd_info.handleType = VK_EXTERNAL_MEMORY_HANDLE_TYPE_OPAQUE_FD_BIT;
  const VkResult result = f_.GetMemoryFdKHR(device_, &fd_info, fd);
  if (result != VK_SUCCESS) {
    *error = "could not export the image's memory: " + result_name(result);
    release_between();
    return false;
  }
  VkMemoryRequirements needs{};
  f_.GetImageMemoryRequirements(device_, between_image_, &needs);
  *memory_size = needs.size;
  return true;
}

bool Transport::submit(VkCommandBuffer commands, VkFence fence, const pfx_vk_image& image, bool wait, bool signal,
                       std::string* error) {
  return submit_frame(f_, queue_, commands, fence, image, VK_PIPELINE_STAGE_TRANSFER_BIT, wait, signal, error);
}

}  // namespace pfx::vk
