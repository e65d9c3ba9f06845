#include "upload_ring.hpp"

namespace pfx_tiledlights {

UploadRing::~UploadRing() {
  for (Slot& slot : slots_) {
    if (slot.fence) glDeleteSync(slot.fence);
    if (slot.buffer) {
      glUnmapNamedBuffer(slot.buffer);
      glDeleteBuffers(1, &slot.buffer);
    }
  }
}

unsigned char* UploadRing::begin(size_t bytes) {
  current_ = (current_ + 1) % kSlots;
  Slot& slot = slots_[current_];
  if (slot.fence) {
    // Polling first tells a wait that costs time from one that does not.
    GLenum state = glClientWaitSync(slot.fence, 0, 0);
    if (state == GL_TIMEOUT_EXPIRED) {
      ++waits_;
      do state = glClientWaitSync(slot.fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000ull);
      while (state == GL_TIMEOUT_EXPIRED);
    }
    glDeleteSync(slot.fence);
    slot.fence = nullptr;
  }
  if (bytes > slot.capacity || !slot.buffer) {
    if (slot.buffer) {
      glUnmapNamedBuffer(slot.buffer);
      glDeleteBuffers(1, &slot.buffer);
    }
    // Grow by half again, so a slowly rising light count does not reallocate every frame.
    size_t capacity = slot.capacity + slot.capacity / 2;
    if (capacity < bytes) capacity = bytes;
    if (capacity < 4096) capacity = 4096;
    const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    glCreateBuffers(1, &slot.buffer);
    glNamedBufferStorage(slot.buffer, static_cast<GLsizeiptr>(capacity), nullptr, flags);
    slot.mapping = glMapNamedBufferRange(slot.buffer, 0, static_cast<GLsizeiptr>(capacity), flags);
    slot.capacity = slot.mapping ? capacity : 0;
  }
  return static_cast<unsigned char*>(slot.mapping);
}

void UploadRing::end() {
  Slot& slot = slots_[current_];
  if (slot.fence) glDeleteSync(slot.fence);
  slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

uint64_t UploadRing::bytes() const {
  uint64_t total = 0;
  for (const Slot& slot : slots_) total += slot.capacity;
  return total;
}

}  // namespace pfx_tiledlights
