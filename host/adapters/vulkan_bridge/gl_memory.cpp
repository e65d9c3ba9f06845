#include "gl_memory.hpp"

#include <unistd.h>

#include <cstring>

#include "headless_context.hpp"

namespace pfx::vk {
namespace {

// From GL_EXT_memory_object and GL_EXT_memory_object_fd (the Khronos registry's glext.h).
constexpr GLenum kTextureTiling = 0x9580;
constexpr GLenum kOptimalTiling = 0x9584;
constexpr GLenum kDeviceUuid = 0x9597;
constexpr GLenum kDriverUuid = 0x9598;
constexpr GLenum kNumDeviceUuids = 0x9596;
constexpr GLenum kHandleTypeOpaqueFd = 0x9586;

bool has_extension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const char* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (extension && std::strcmp(extension, name) == 0) return true;
  }
  return false;
}

template <typename Fn>
Fn lookup(const char* name) {
  return reinterpret_cast<Fn>(app::HeadlessContext::get_proc_address(nullptr, name));
}

}  // namespace

bool GlMemory::check(const uint8_t device_uuid[16], const uint8_t driver_uuid[16], std::string* why) {
  if (!has_extension("GL_EXT_memory_object") || !has_extension("GL_EXT_memory_object_fd")) {
    *why = "the GL offers no GL_EXT_memory_object_fd";
    return false;
  }
  create_memory_objects_ = lookup<CreateMemoryObjects>("glCreateMemoryObjectsEXT");
  delete_memory_objects_ = lookup<DeleteMemoryObjects>("glDeleteMemoryObjectsEXT");
  import_memory_fd_ = lookup<ImportMemoryFd>("glImportMemoryFdEXT");
  texture_storage_mem_2d_ = lookup<TextureStorageMem2D>("glTextureStorageMem2DEXT");
  texture_storage_mem_3d_ = lookup<TextureStorageMem3D>("glTextureStorageMem3DEXT");
  get_unsigned_bytev_ = lookup<GetUnsignedBytev>("glGetUnsignedBytevEXT");
  get_unsigned_bytei_v_ = lookup<GetUnsignedBytei_v>("glGetUnsignedBytei_vEXT");
  if (!create_memory_objects_ || !delete_memory_objects_ || !import_memory_fd_ || !texture_storage_mem_2d_ ||
      !texture_storage_mem_3d_ || !get_unsigned_bytev_ || !get_unsigned_bytei_v_) {
    *why = "the GL names GL_EXT_memory_object_fd but does not give its functions";
    return false;
  }
  GLubyte driver[16] = {};
  get_unsigned_bytev_(kDriverUuid, driver);
  if (std::memcmp(driver, driver_uuid, 16) != 0) {
    *why = "the GL's driver is not the Vulkan device's (driver UUIDs differ)";
    return false;
  }
  // A GL context may span several devices (SLI); the Vulkan device must be one of them.
  GLint devices = 0;
  glGetIntegerv(kNumDeviceUuids, &devices);
  for (GLint i = 0; i < devices; ++i) {
    GLubyte device[16] = {};
    get_unsigned_bytei_v_(kDeviceUuid, static_cast<GLuint>(i), device);
    if (std::memcmp(device, device_uuid, 16) == 0) return glGetError() == GL_NO_ERROR;
  }
  *why = "the GL's device is not the Vulkan device (device UUIDs differ)";
  return false;
}

void GlMemory::release() {
  for (gl::EightBitTexture& layer : layers_) layer.release();
  if (texture_) glDeleteTextures(1, &texture_);
  if (memory_ && delete_memory_objects_) delete_memory_objects_(1, &memory_);
  texture_ = memory_ = 0;
}

bool GlMemory::import(int fd, uint64_t memory_size, int width, int height, Between between, std::string* error) {
  release();
  while (glGetError() != GL_NO_ERROR) {
  }
  create_memory_objects_(1, &memory_);
  import_memory_fd_(memory_, memory_size, kHandleTypeOpaqueFd, fd);
  if (glGetError() != GL_NO_ERROR) {
    // The descriptor passes to the GL only when the import succeeds.
    close(fd);
    *error = "the GL could not import the Vulkan image's memory";
    release();
    return false;
  }
  glCreateTextures(between.blits ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, 1, &texture_);
  glTextureParameteri(texture_, kTextureTiling, static_cast<GLint>(kOptimalTiling));
  if (between.blits) {
    // The Vulkan image's own format, then a 2D view of each layer in both readings.
    texture_storage_mem_3d_(texture_, 1, between.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, width, height, 2, memory_, 0);
    for (GLuint index = 0; index < 2; ++index) {
      gl::EightBitTexture& layer = layers_[index];
      glGenTextures(1, &layer.texture);
      glTextureView(layer.texture, GL_TEXTURE_2D, texture_, GL_RGBA8, 0, 1, index, 1);
      glGenTextures(1, &layer.srgb_view);
      glTextureView(layer.srgb_view, GL_TEXTURE_2D, texture_, GL_SRGB8_ALPHA8, 0, 1, index, 1);
    }
  } else {
    texture_storage_mem_2d_(texture_, 1, between.ten_bit ? GL_RGB10_A2 : GL_RGBA8, width, height, memory_, 0);
  }
  if (glGetError() != GL_NO_ERROR) {
    *error = "the GL could not make a texture over the Vulkan image's memory";
    release();
    return false;
  }
  return true;
}

}  // namespace pfx::vk
