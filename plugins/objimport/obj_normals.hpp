// Normals for the vertices whose corners gave none: area-weighted face normals (the cross product
// of two edges, whose length is twice the triangle's area), summed over the triangles that share
// a position within one smoothing group, then made unit length. A corner of a face with smoothing
// off gets its face's normal alone. A sum of zero (only degenerate triangles) gives (0, 0, 1).
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/services.h>

#include "obj_dedup.hpp"

namespace pfx_obj {

// normals: 3 per vertex; those of vertices with keys[i].vn == kNoIndex are overwritten.
// Deterministic: every sum runs in index order whatever the thread count. On at most `threads`
// workers of `pool` (null: on the calling thread).
void generate_normals(const BigVector<VertexKey>& keys, const BigVector<float>& positions,
                      const BigVector<uint32_t>& indices, const pfx_thread_pool* pool, unsigned threads,
                      BigVector<float>* normals);

}  // namespace pfx_obj
