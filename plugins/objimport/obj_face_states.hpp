// The material and normal group of each face of a chunk, found while walking its faces in order:
// the state in force at the chunk's start (from the serial plan) changed by the chunk's own usemtl
// and s statements. The walks that need them (dedup, triangles) compute them on the way instead of
// reading two arrays with an entry per face.
#pragma once

#include <cstdint>
#include <vector>

#include "obj_chunk.hpp"

namespace pfx_obj {

// Smoothing group of faces before any `s` statement: smoothed together, as if `s 1`.
constexpr uint32_t kDefaultSmoothing = 1;
// Normal group of a face with smoothing off: its own ordinal in the file, marked by the top bit.
constexpr uint32_t kFlatFaceBit = 0x80000000u;

class FaceStates {
 public:
  FaceStates() = default;
  // material_slots: the slot of each of the chunk's material names; start_slot: the slot in force
  // at the chunk's start; face_base: the file ordinal of the chunk's first face.
  FaceStates(const std::vector<StateChange>* changes, const std::vector<uint32_t>* material_slots, uint32_t start_slot,
             uint32_t start_smoothing, uint64_t face_base)
      : changes_(changes), material_slots_(material_slots), slot_(start_slot), smoothing_(start_smoothing),
        face_base_(face_base) {}

  // Moves to chunk-local face f; call with f = 0, 1, 2, ... in order.
  void at_face(uint64_t f) {
    for (; next_ < changes_->size() && (*changes_)[next_].first_face == f; ++next_) {
      const StateChange& change = (*changes_)[next_];
      if (change.kind == StateChange::kMaterial) slot_ = (*material_slots_)[change.value];
      else smoothing_ = change.value;
    }
    face_ = f;
  }
  uint32_t slot() const { return slot_; }
  // Faces of one smoothing group share generated normals; a face with smoothing off has its own.
  uint32_t normal_group() const {
    return smoothing_ == 0 ? (kFlatFaceBit | static_cast<uint32_t>(face_base_ + face_)) : smoothing_;
  }

 private:
  const std::vector<StateChange>* changes_ = nullptr;
  const std::vector<uint32_t>* material_slots_ = nullptr;
  uint32_t slot_ = 0, smoothing_ = kDefaultSmoothing;
  uint64_t face_base_ = 0, face_ = 0;
  size_t next_ = 0;
};

}  // namespace pfx_obj
