// Stages 5 and 6 of an import (obj_stages.hpp): the result's index array, one sub-mesh per
// material, and its vertex arrays.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "obj_parallel.hpp"
#include "obj_stages.hpp"

namespace pfx_obj {

namespace {

constexpr size_t kBlock = size_t{1} << 15;  // vertices per parallel task

// A usemtl name's (an index into FileStatements::material_names) place among the sub-meshes: its
// material's index, or one past the last material for faces before any usemtl.
uint32_t slot_of(const MaterialTable& table, uint32_t name) {
  return name == kNoIndex ? static_cast<uint32_t>(table.materials.size()) : table.of_name[name];
}

// run(slot, first, end) for each run of the chunk's triangles of one material, in order: the
// triangles [first, end) of the file's.
template <typename Run>
void for_each_run(const NumberedChunk& chunk, const MaterialTable& table, Run run) {
  uint32_t slot = slot_of(table, chunk.start.material);
  uint64_t first = chunk.start.triangles;
  for (const StateChange& change : chunk.changes) {
    if (change.kind != StateChange::kMaterial) continue;
    const uint64_t at = chunk.start.triangles + change.first_triangle;
    if (at > first) run(slot, first, at);
    slot = slot_of(table, change.value);
    first = at;
  }
  if (chunk.end.triangles > first) run(slot, first, chunk.end.triangles);
}

// Each vertex's kWidth floats of *source at the element its key's `field` names (zeros for none),
// in blocks on every worker; *source freed after.
template <int kWidth>
BigVector<float> gather(const BigVector<VertexKey>& keys, BigVector<float>* source, uint32_t VertexKey::*field,
                        const pfx_thread_pool* pool, unsigned threads) {
  const size_t count = keys.size();
  BigVector<float> out(kWidth * count);
  run_parallel(pool, threads, (count + kBlock - 1) / kBlock, [&](size_t b, unsigned) {
    for (size_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
      const uint32_t element = keys[i].*field;
      for (int k = 0; k < kWidth; ++k) out[kWidth * i + k] = element == kNoIndex ? 0.0f : (*source)[kWidth * size_t{element} + k];
    }
  });
  free_array(source);
  return out;
}

}  // namespace

TriangleIndex index_by_material(const std::vector<NumberedChunk>& chunks, const MaterialTable& materials,
                                BigVector<uint32_t> triangles) {
  const size_t slots = materials.materials.size() + 1;
  std::vector<uint64_t> count(slots, 0), first_use(slots, ~uint64_t{0});
  for (const NumberedChunk& chunk : chunks)
    for_each_run(chunk, materials, [&](uint32_t s, uint64_t first, uint64_t end) {
      count[s] += end - first;
      first_use[s] = std::min(first_use[s], first);
    });
  std::vector<uint32_t> order;  // the slots used, in order of first use
  for (uint32_t s = 0; s < slots; ++s)
    if (count[s] > 0) order.push_back(s);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return first_use[a] < first_use[b]; });

  TriangleIndex index;
  std::vector<uint64_t> place(slots, 0);  // where each slot's next triangle goes
  uint64_t total = 0;
  for (uint32_t s : order) {
    place[s] = total;
    total += 3 * count[s];
    const uint32_t material = s == slots - 1 ? kNoIndex : s;
    index.submeshes.push_back({static_cast<uint32_t>(place[s]), static_cast<uint32_t>(3 * count[s]), material});
  }
  if (order.size() <= 1) {  // one material: the triangles as they are
    index.indices = std::move(triangles);
    return index;
  }
  index.indices.resize(total);
  for (const NumberedChunk& chunk : chunks)
    for_each_run(chunk, materials, [&](uint32_t s, uint64_t first, uint64_t end) {
      std::memcpy(&index.indices[place[s]], &triangles[3 * first], 3 * (end - first) * sizeof(uint32_t));
      place[s] += 3 * (end - first);
    });
  return index;
}

MeshVertices gather_vertices(const BigVector<VertexKey>& keys, FileVertices file, const pfx_thread_pool* pool,
                             unsigned threads) {
  MeshVertices mesh;
  mesh.positions = gather<3>(keys, &file.positions, &VertexKey::v, pool, threads);
  if (!file.colors.empty()) mesh.colors = gather<3>(keys, &file.colors, &VertexKey::v, pool, threads);
  if (std::any_of(keys.begin(), keys.end(), [](const VertexKey& k) { return k.vt != kNoIndex; }))
    mesh.texcoords = gather<2>(keys, &file.texcoords, &VertexKey::vt, pool, threads);
  mesh.normals = gather<3>(keys, &file.normals, &VertexKey::vn, pool, threads);  // those without: generated later
  free_array(&file.texcoords);  // when no corner used one
  if (keys.empty()) return mesh;  // the bounds stay zero
  std::fill_n(mesh.bounds_min, 3, HUGE_VALF);
  std::fill_n(mesh.bounds_max, 3, -HUGE_VALF);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    mesh.bounds_min[i % 3] = std::min(mesh.bounds_min[i % 3], mesh.positions[i]);
    mesh.bounds_max[i % 3] = std::max(mesh.bounds_max[i % 3], mesh.positions[i]);
  }
  return mesh;
}

}  // namespace pfx_obj
