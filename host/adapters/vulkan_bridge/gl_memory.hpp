// The GL half of sharing memory with Vulkan (GL_EXT_memory_object, GL_EXT_memory_object_fd): the
// UUIDs that say whether the GL device is the Vulkan device, and a texture over memory Vulkan
// exported. The generated GL loader holds no extensions, so their few functions are looked up here.
#pragma once

#include <cstdint>
#include <string>

#include <glad/gl.h>

#include "eight_bit_texture.hpp"
#include "vk_transport.hpp"

namespace pfx::vk {

class GlMemory {
 public:
  // With the bridge's context current: false with *why when the GL cannot import memory
  // (an extension missing) or its device is not the one whose UUIDs are given.
  bool check(const uint8_t device_uuid[16], const uint8_t driver_uuid[16], std::string* why);
  // A texture over `fd` (taken: the GL owns it afterwards, closed here on failure) of
  // `memory_size` bytes holding the width x height optimal-tiling go-between `between` describes
  // (vk_transport.hpp): with blits, an array of two layers, each also viewed as the 8-bit texture
  // layer() gives; else one texture of 32-bit texels, RGBA8, or RGB10_A2 when ten_bit. Replaces
  // the last one.
  bool import(int fd, uint64_t memory_size, int width, int height, Between between, std::string* error);
  GLuint texture() const { return texture_; }
  // With blits: layer 0, the frame as it came, or 1, the frame as it goes out.
  const gl::EightBitTexture& layer(int index) const { return layers_[index]; }
  void release();
  ~GlMemory() { release(); }

 private:
  using CreateMemoryObjects = void (GLAD_API_PTR*)(GLsizei, GLuint*);
  using DeleteMemoryObjects = void (GLAD_API_PTR*)(GLsizei, const GLuint*);
  using ImportMemoryFd = void (GLAD_API_PTR*)(GLuint, GLuint64, GLenum, GLint);
  using TextureStorageMem2D = void (GLAD_API_PTR*)(GLuint, GLsizei, GLenum, GLsizei, GLsizei, GLuint, GLuint64);
  using TextureStorageMem3D = void (GLAD_API_PTR*)(GLuint, GLsizei, GLenum, GLsizei, GLsizei, GLsizei, GLuint,
                                                    GLuint64);
  using GetUnsignedBytev = void (GLAD_API_PTR*)(GLenum, GLubyte*);
  using GetUnsignedBytei_v = void (GLAD_API_PTR*)(GLenum, GLuint, GLubyte*);
  CreateMemoryObjects create_memory_objects_ = nullptr;
  DeleteMemoryObjects delete_memory_objects_ = nullptr;
  ImportMemoryFd import_memory_fd_ = nullptr;
  TextureStorageMem2D texture_storage_mem_2d_ = nullptr;
  TextureStorageMem3D texture_storage_mem_3d_ = nullptr;
  GetUnsignedBytev get_unsigned_bytev_ = nullptr;
  GetUnsignedBytei_v get_unsigned_bytei_v_ = nullptr;
  GLuint memory_ = 0, texture_ = 0;
  gl::EightBitTexture layers_[2];
};

}  // namespace pfx::vk
