#include "cpu_culling.hpp"

#include <algorithm>

namespace pfx_tiledlights {
namespace {

void centre_of(const GpuLight& light, double out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = light.view[k];
}

}  // namespace

std::vector<uint32_t> lights_in_view(const LightSet& set, const Perspective& perspective, int width, int height,
                                     double near_depth, double far_depth) {
  const SidePlanes frame = side_planes(perspective, width, height, 0, width, 0, height);
  std::vector<uint32_t> visible;
  visible.reserve(set.lights.size());
  for (uint32_t i = 0; i < set.lights.size(); ++i) {
    double c[3];
    centre_of(set.lights[i], c);
    const double r = set.lights[i].cull_radius;
    if (sphere_touches_depths(c, r, near_depth, far_depth) && sphere_touches(frame, c, r)) visible.push_back(i);
  }
  return visible;
}

bool cull_grid(const LightSet& set, const std::vector<uint32_t>& candidates, const Perspective& perspective,
               int width, int height, int tiles_x, int tiles_y, GridLists* out) {
  out->tiles_x = tiles_x;
  out->tiles_y = tiles_y;
  const size_t tiles = size_t(tiles_x) * tiles_y;
  // A tile's left/right planes involve only x and z, its bottom/top planes only y and z, so a
  // sphere reaches tile (i, j) exactly when it passes column i's planes and row j's planes: test
  // columns and rows once per light (tiles_x + tiles_y tests, not tiles_x * tiles_y).
  std::vector<SidePlanes> columns(tiles_x), rows(tiles_y);
  std::vector<bool> column_empty(tiles_x), row_empty(tiles_y);
  for (int i = 0; i < tiles_x; ++i) {
    const int x0 = grid_tile_first_pixel(i, tiles_x, width), x1 = grid_tile_first_pixel(i + 1, tiles_x, width);
    column_empty[i] = x0 == x1;  // more tiles than pixels: some hold no pixel
    columns[i] = side_planes(perspective, width, height, x0, x1, 0, height);
  }
  for (int j = 0; j < tiles_y; ++j) {
    const int y0 = grid_tile_first_pixel(j, tiles_y, height), y1 = grid_tile_first_pixel(j + 1, tiles_y, height);
    row_empty[j] = y0 == y1;
    rows[j] = side_planes(perspective, width, height, 0, width, y0, y1);
  }
  auto passes = [](const SidePlanes& planes, int first, const double c[3], double r) {
    for (int p = first; p < first + 2; ++p)
      if (planes.n[p][0] * c[0] + planes.n[p][1] * c[1] + planes.n[p][2] * c[2] < -r) return false;
    return true;
  };

  // Two sweeps over the lights in order: count, then fill, so every list is in increasing order
  // and the shading sums lights in the order brute force does.
  std::vector<uint32_t> counts(tiles, 0);
  std::vector<int> hit_columns, hit_rows;
  auto for_each_tile = [&](const GpuLight& light, auto&& visit) {
    double c[3];
    centre_of(light, c);
    const double r = light.cull_radius;
    hit_columns.clear();
    hit_rows.clear();
    for (int i = 0; i < tiles_x; ++i)
      if (!column_empty[i] && passes(columns[i], 0, c, r)) hit_columns.push_back(i);
    if (hit_columns.empty()) return;
    for (int j = 0; j < tiles_y; ++j)
      if (!row_empty[j] && passes(rows[j], 2, c, r)) hit_rows.push_back(j);
    for (int j : hit_rows)
      for (int i : hit_columns) visit(size_t(j) * tiles_x + i);
  };
  for (uint32_t k = 0; k < candidates.size(); ++k)
    for_each_tile(set.lights[candidates[k]], [&](size_t tile) { ++counts[tile]; });

  out->heads.assign(tiles * 2, 0);
  uint64_t offset = 0;
  out->stats = ListStats{};
  out->stats.lists = tiles;
  for (size_t t = 0; t < tiles; ++t) {
    out->heads[t * 2] = static_cast<uint32_t>(offset);
    offset += counts[t];
    out->stats.max_length = std::max(out->stats.max_length, counts[t]);
  }
  out->stats.entries = offset;
  if (offset > 0xffffffffull) return false;
  out->indices.assign(offset, 0);
  std::vector<uint32_t> filled(tiles, 0);
  for (uint32_t k = 0; k < candidates.size(); ++k)
    for_each_tile(set.lights[candidates[k]], [&](size_t tile) {
      out->indices[out->heads[tile * 2] + filled[tile]++] = k;
    });
  for (size_t t = 0; t < tiles; ++t) out->heads[t * 2 + 1] = counts[t];
  return true;
}

}  // namespace pfx_tiledlights
