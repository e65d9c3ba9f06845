// Resolution, chunk by chunk in parallel (obj_importer.hpp): each chunk's triangle counts per
// material slot, and its relative indices made final with every index checked against the file's
// totals — a walk over the corners that only chunks with relative or out-of-range indices need.
#include <algorithm>

#include "obj_importer.hpp"
#include "obj_parallel.hpp"

namespace pfx_obj {

void Importer::resolve_all(unsigned threads) {
  faces_.assign(chunks_.size(), ChunkFaces{});
  const size_t slots = out_->materials.size() + 1;  // the last slot: no material
  run_parallel(options_.pool, threads, chunks_.size(), [&](size_t c, unsigned) { resolve(c, slots); });
}

void Importer::resolve(size_t c, size_t slots) {
  ChunkData& chunk = chunks_[c];
  ChunkPlan& plan = plans_[c];
  ChunkFaces& result = faces_[c];
  plan.start_slot = plan.start_material == kNoIndex ? static_cast<uint32_t>(slots - 1) : plan.start_material;
  result.triangle_counts.assign(slots, 0);
  result.first_use.assign(slots, ~uint64_t{0});
  for (size_t m = 0; m < chunk.triangles_by_material.size(); ++m) {
    if (chunk.first_face_by_material[m] == ChunkData::kNoFace) continue;
    const uint32_t slot = m == 0 ? plan.start_slot : plan.material_slots[m - 1];
    result.triangle_counts[slot] += chunk.triangles_by_material[m];
    result.first_use[slot] = std::min(result.first_use[slot], plan.face_base + chunk.first_face_by_material[m]);
  }
  // Positive indices are stored final: only relative ones, or an index past the file's last
  // element (an error), need a walk over the corners.
  if (chunk.relative_fields.empty() && chunk.max_index[0] <= totals_[0] && chunk.max_index[1] <= totals_[1] &&
      chunk.max_index[2] <= totals_[2])
    return;
  const char* kinds[3] = {"v", "vt", "vn"};
  const uint32_t bases[3] = {plan.position_base, plan.texcoord_base, plan.normal_base};
  uint64_t field = 0;
  for (size_t f = 0; f < chunk.faces.size(); ++f) {
    const Face& face = chunk.faces[f];
    for (uint32_t k = 0; k < face.corner_count; ++k) {
      for (int j = 0; j < 3; ++j, ++field) {
        uint32_t& value = chunk.corners[field];
        // A relative index may be stored as kNoIndex (-1: it reaches two elements back before
        // the chunk): only a field not marked relative can mean "absent".
        const bool relative = chunk.is_relative(field);
        if (!relative && value == kNoIndex) continue;
        const int64_t one_based = relative ? int64_t{bases[j]} + static_cast<int32_t>(value) : int64_t{value} + 1;
        if (relative && one_based < 1) {
          result.failed = true;
          result.error = {plan.first_line + face.line,
                          std::string("f: relative ") + kinds[j] + " index reaches before the first " + kinds[j]};
          return;
        }
        if (one_based > totals_[j]) {
          result.failed = true;
          result.error = {plan.first_line + face.line,
                          totals_[j] == 0 ? std::string("f: ") + kinds[j] + " index " + std::to_string(one_based) +
                                                " but the file has no " + kinds[j]
                                          : std::string("f: ") + kinds[j] + " index " + std::to_string(one_based) +
                                                " is out of range (the file has " + std::to_string(totals_[j]) +
                                                " " + kinds[j] + ")"};
          return;
        }
        value = static_cast<uint32_t>(one_based - 1);
      }
    }
  }
  free_array(&chunk.relative_fields);
}

bool Importer::first_resolve_error(std::string* error) {
  for (const ChunkFaces& f : faces_)
    if (f.failed) {
      *error = at(name_, f.error.line, f.error.text);
      return false;
    }
  return true;
}

// The material slot and normal group of chunk c's faces, walked in order.
FaceStates Importer::face_states(size_t c) const {
  const ChunkPlan& plan = plans_[c];
  return FaceStates(&chunks_[c].changes, &plan.material_slots, plan.start_slot, plan.start_smoothing, plan.face_base);
}

}  // namespace pfx_obj
