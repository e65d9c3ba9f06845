// One vertex per distinct face corner. A corner is keyed by its full 32-bit indices — position,
// texture coordinate, normal — plus, for a corner without a normal, the smoothing group its
// normal will be generated for (obj_import.cpp). Nothing is packed, so nothing collides: the
// seed's 21-bit packing merged distinct corners past 2^21 elements.
//
// With several threads, chunks are deduplicated on their own in parallel, their distinct keys are
// then merged in file order, and their corners renumbered in parallel. Vertices are numbered in the
// order of their first corner in the file, whatever the thread count, so the output never depends
// on it.
#pragma once

#include <cstdint>
#include <vector>

#include "obj_buffer.hpp"
#include "obj_chunk.hpp"
#include "obj_face_states.hpp"
#include "obj_stages.hpp"

namespace pfx_obj {

struct VertexKey {
  uint32_t v;      // 0-based position index
  uint32_t vt;     // 0-based texture coordinate index, or kNoIndex
  uint32_t vn;     // 0-based normal index, or kNoIndex
  uint32_t group;  // 0 when vn is given; otherwise which generated normal (see obj_import.cpp)
  bool operator==(const VertexKey& o) const { return v == o.v && vt == o.vt && vn == o.vn && group == o.group; }
};

// The corners of one chunk after resolution: three fields per corner (0-based or kNoIndex), the
// faces, and their states (for each face's normal group).
struct DedupChunk {
  const uint32_t* corners = nullptr;  // 3 per corner
  uint64_t corner_count = 0;
  const Face* faces = nullptr;
  uint64_t face_count = 0;
  FaceStates states;  // each face's normal group
};

// vertices: the distinct keys in order of first use. corner_vertex[c][k]: the vertex of corner k
// of chunk c.
// position_count: how many positions the file has (every corner's v is below it).
// clock: times its phases (with threads: the chunks in parallel, the serial merge, the renumbering).
void deduplicate(const std::vector<DedupChunk>& chunks, uint32_t position_count, unsigned threads,
                 BigVector<VertexKey>* vertices, std::vector<BigVector<uint32_t>>* corner_vertex, StageClock* clock);

}  // namespace pfx_obj
