// Per-frame data for the GPU (lights, CPU-built lists) in a ring of persistently mapped, coherent
// buffers. A plain double buffer without a fence, so nothing stops the CPU from overwriting a
// buffer the GPU is still reading; here every slot carries a fence set after the last draw that
// reads it, and writing a slot again first waits for that fence.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glad/gl.h>

namespace pfx_tiledlights {

class UploadRing {
 public:
  static constexpr int kSlots = 3;
  UploadRing() = default;
  ~UploadRing();
  UploadRing(const UploadRing&) = delete;
  UploadRing& operator=(const UploadRing&) = delete;

  // Starts a frame: waits until the GPU is done with the next slot, grows it to hold `bytes`, and
  // returns its mapping (null when the GL could not make the buffer).
  unsigned char* begin(size_t bytes);
  GLuint buffer() const { return slots_[current_].buffer; }
  // Which slot this frame uses: data the GPU writes for the frame (the GPU-built lists) is kept
  // per slot too, so the same fence guards it.
  int slot() const { return current_; }
  // Fences the current slot after the last command that reads it.
  void end();

  uint64_t waits() const { return waits_; }         // begins that had to wait for the GPU
  uint64_t bytes() const;                          // all slots' storage

 private:
  struct Slot {
    GLuint buffer = 0;
    void* mapping = nullptr;
    size_t capacity = 0;
    GLsync fence = nullptr;
  };
  Slot slots_[kSlots];
  int current_ = kSlots - 1;
  uint64_t waits_ = 0;
};

}  // namespace pfx_tiledlights
