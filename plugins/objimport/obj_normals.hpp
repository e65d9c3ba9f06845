// Normals for the vertices whose corners gave none: area-weighted face normals (the cross product
// of two edges, whose length is twice the triangle's area), summed over the triangles that share
// a position within one smoothing group, then made unit length. A corner of a face with smoothing
// off gets its face's normal alone. A sum of zero (only degenerate triangles) gives (0, 0, 1).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <pfx/services.h>

#include "obj_dedup.hpp"
#include "obj_parallel.hpp"

namespace pfx_obj {

// normals: 3 per vertex; those of vertices with keys[i].vn == kNoIndex are overwritten.
// Deterministic: every sum runs in index order whatever the thread count. On at most `threads`
// workers of `pool` (null: on the calling thread).
inline void generate_normals(const BigVector<VertexKey>& keys, const BigVector<float>& positions,
                             const BigVector<uint32_t>& indices, const pfx_thread_pool* pool, unsigned threads,
                             BigVector<float>* normals) {
  const size_t count = keys.size();
  const unsigned workers = threads < 1 ? 1 : threads;
  BigVector<float>& n = *normals;
  // Which vertices get a generated normal (their sums zeroed): in a file that gives every corner a
  // normal, none, and this is all the stage does.
  std::vector<uint8_t> generated(count);
  bool any = false, with_texcoords = false;
  for (size_t i = 0; i < count; ++i) {
    const bool generate = keys[i].vn == kNoIndex;
    generated[i] = generate;
    if (!generate) continue;
    any = true;
    with_texcoords |= keys[i].vt != kNoIndex;
    n[3 * i] = n[3 * i + 1] = n[3 * i + 2] = 0.0f;
  }
  if (!any) return;

  // Each worker owns a range of vertices and adds every triangle's normal to the ones it owns, in
  // index order: no two workers write one vertex, and the order of each sum is fixed.
  run_workers(pool, workers, [&](unsigned w) {
    const uint64_t lo = count * w / workers, hi = count * (w + 1) / workers;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
      auto owns = [&](uint32_t v) { return v >= lo && v < hi && generated[v]; };
      if (!owns(a) && !owns(b) && !owns(c)) continue;
      const float *pa = &positions[3 * size_t{a}], *pb = &positions[3 * size_t{b}], *pc = &positions[3 * size_t{c}];
      const float e1[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
      const float e2[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
      const float cross[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                              e1[0] * e2[1] - e1[1] * e2[0]};
      for (uint32_t v : {a, b, c})
        if (owns(v))
          for (int k = 0; k < 3; ++k) n[3 * size_t{v} + k] += cross[k];
    }
  });

  // Vertices that differ only by texture coordinate (a UV seam) share a position and smoothing
  // group, so they must share one normal: add their sums, in vertex order.
  if (with_texcoords) {
    std::unordered_map<VertexKey, uint32_t, VertexKeyHash> first_of;  // its first vertex
    std::vector<uint32_t> representative(count, kNoIndex);
    for (size_t i = 0; i < count; ++i) {
      if (!generated[i]) continue;
      const auto [it, fresh] = first_of.emplace(VertexKey{keys[i].v, kNoIndex, kNoIndex, keys[i].group}, uint32_t(i));
      representative[i] = it->second;
      if (!fresh)
        for (int k = 0; k < 3; ++k) n[3 * size_t{it->second} + k] += n[3 * i + k];
    }
    for (size_t i = 0; i < count; ++i)
      if (generated[i] && representative[i] != i)
        for (int k = 0; k < 3; ++k) n[3 * i + k] = n[3 * size_t{representative[i]} + k];
  }

  run_parallel(pool, workers, workers, [&](size_t w, unsigned) {
    const uint64_t lo = count * w / workers, hi = count * (w + 1) / workers;
    for (uint64_t i = lo; i < hi; ++i) {
      if (!generated[i]) continue;
      float* v = &n[3 * i];
      const double length = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
      if (length > 0 && std::isfinite(length)) {
        for (int k = 0; k < 3; ++k) v[k] = static_cast<float>(v[k] / length);
      } else {
        v[0] = v[1] = 0.0f;
        v[2] = 1.0f;
      }
    }
  });
}

}  // namespace pfx_obj
