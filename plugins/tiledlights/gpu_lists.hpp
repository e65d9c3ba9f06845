// The `tiled` and `clustered` light lists, built on the GPU in the layout of Olsson's clustered
// shading: a head (offset, count) per tile or cluster and one compact index array holding every
// list back to back, so a list is as long as its tile or cluster needs, at any density.
//
// Per frame: the count phase (each list's length, each tile's depth bounds), a prefix sum over the
// lengths (offsets, the total), the fill phase (the indices). The index buffer must hold the
// total before the fill runs. The CPU's bound of the total (list_bound.hpp) sizes it without
// waiting for the GPU; only when that bound is past the budget (the GL's shader storage limit, or
// the user's max_list_indices) is the exact total read back before the fill — a wait for the GPU
// in that frame, counted in the report — and a frame whose exact total is past the budget is
// refused with an error. No list is ever cut short or replaced by every light.
#pragma once

#include <cstdint>
#include <string>

#include <glad/gl.h>

#include "upload_ring.hpp"

namespace pfx_tiledlights {

// An offset into a buffer rounded up to a multiple of GL's storage-buffer offset alignment, so a
// range of one buffer can be bound on its own.
inline size_t align_up(size_t value, size_t alignment) { return (value + alignment - 1) / alignment * alignment; }

struct ListShape {
  bool clustered = false;
  int tiles_x = 0, tiles_y = 0, slices = 1;
  uint64_t lists() const { return uint64_t(tiles_x) * tiles_y * (clustered ? slices : 1); }
};

class GpuLists {
 public:
  GpuLists() = default;
  ~GpuLists();
  GpuLists(const GpuLists&) = delete;
  GpuLists& operator=(const GpuLists&) = delete;

  // Compiles the programs. False with *error naming the shader.
  bool create(std::string* error);
  // The count/fill program of a mode, for the caller to set the frame's uniforms on.
  GLuint program(bool clustered) const { return clustered ? clustered_ : tiled_; }

  // Builds the lists of one frame in the ring slot's buffers (the lights bound at SSBO_LIGHTS, the
  // depth at texture unit 0, the program's frame uniforms set). bound: the CPU's bound of the
  // entries; budget: the most indices the index buffer may hold. False with *error when the lists
  // need more.
  bool build(int slot, const ListShape& shape, uint64_t bound, uint64_t budget, std::string* error);
  // Binds the slot's heads and indices for the shading pass.
  void bind_for_shading(int slot) const;

  struct Stats {
    uint64_t entries = 0;        // indices in all lists
    uint32_t longest = 0;
    uint32_t inconsistent = 0;   // lists the fill found a different length for than the count (a bug)
  };
  // The last build's figures: waits for it.
  Stats read_stats() const;
  uint64_t index_capacity(int slot) const { return slots_[slot].index_capacity; }
  uint64_t readbacks() const { return readbacks_; }  // builds that had to wait for the exact total
  uint64_t bytes() const;                            // storage of every slot, and the counters

 private:
  struct Slot {
    GLuint heads = 0;   // heads (uvec2 per list), then the tiles' depth bounds (uvec2 per tile)
    size_t heads_bytes = 0;
    GLuint indices = 0;
    uint64_t index_capacity = 0;  // indices
  };
  bool reserve_indices(Slot* slot, uint64_t needed, uint64_t budget);
  void dispatch(GLuint program, int phase, const ListShape& shape);

  GLuint tiled_ = 0, clustered_ = 0, prefix_sum_ = 0;
  GLuint stats_ = 0;
  GLint alignment_ = 256;
  Slot slots_[UploadRing::kSlots];
  uint64_t readbacks_ = 0;
  // Layout of the frame being built (the shading pass binds the same ranges).
  size_t list_heads_bytes_ = 0, bounds_offset_ = 0, bounds_bytes_ = 0;
  uint64_t frame_indices_ = 0;
};

}  // namespace pfx_tiledlights
