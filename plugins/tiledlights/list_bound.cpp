#include "list_bound.hpp"

#include <algorithm>
#include <cmath>

namespace pfx_tiledlights {
namespace {

// The unit normal (a, b) in the plane of one axis and z of the side plane through the eye and the
// pixel edge at window coordinate `edge`; a point (u, z) is on the tile's side of the edge's
// "start" plane when a u + b z >= 0. The same formula as the GPU's side planes.
struct EdgePlane {
  double a, b;
};

std::vector<EdgePlane> edge_planes(int tiles, int tile_size, int size, double scale, double offset) {
  std::vector<EdgePlane> planes(tiles + 1);
  for (int i = 0; i <= tiles; ++i) {
    const double edge = std::min<double>(double(i) * tile_size, size);
    const double slope = (2.0 * edge / size - 1.0 + offset) / scale;
    const double length = std::sqrt(1.0 + slope * slope);
    planes[i] = {1.0 / length, slope / length};
  }
  return planes;
}

// How many of the tiles between the edges the sphere (u, z, radius) may reach: tile i when it is
// not wholly before edge i nor wholly past edge i + 1.
uint64_t tiles_reached(const std::vector<EdgePlane>& edges, double u, double z, double radius) {
  uint64_t count = 0;
  for (size_t i = 0; i + 1 < edges.size(); ++i) {
    const double after_start = edges[i].a * u + edges[i].b * z;
    const double before_end = -(edges[i + 1].a * u + edges[i + 1].b * z);
    if (after_start >= -radius && before_end >= -radius) ++count;
  }
  return count;
}

// The slice a view depth falls in, as the GPU's slice_of computes it (in double).
int slice_index(double depth, const ListGrid& grid) {
  if (!(depth > grid.slice_near)) return 0;
  const double s = std::floor(std::log(depth / grid.slice_near) / std::log(grid.slice_far / grid.slice_near) *
                              grid.slices);
  return static_cast<int>(std::clamp(s, 0.0, double(grid.slices - 1)));
}

}  // namespace

uint64_t list_entries_bound(const LightSet& set, const std::vector<uint32_t>& visible, const Perspective& perspective,
                            const ListGrid& grid) {
  const int tiles_x = (grid.width + grid.tile_size - 1) / grid.tile_size;
  const int tiles_y = (grid.height + grid.tile_size - 1) / grid.tile_size;
  const auto columns = edge_planes(tiles_x, grid.tile_size, grid.width, perspective.scale_x, perspective.offset_x);
  const auto rows = edge_planes(tiles_y, grid.tile_size, grid.height, perspective.scale_y, perspective.offset_y);
  uint64_t total = 0;
  for (uint32_t index : visible) {
    const GpuLight& light = set.lights[index];
    const double x = light.view[0], y = light.view[1], z = light.view[2];
    const double centre = std::sqrt(x * x + y * y + z * z);
    const double radius =
        double(light.cull_radius) * (1 + kBoundRelativeMargin) + kBoundAbsoluteMargin * (1 + centre);
    const uint64_t across = tiles_reached(columns, x, z, radius);
    if (across == 0) continue;
    uint64_t reached = across * tiles_reached(rows, y, z, radius);
    if (grid.slices > 0) {
      // The GPU widens each slice by 0.1%; 1% and a slice either side here.
      const int first = std::max(0, slice_index((-z - radius) * 0.99, grid) - 1);
      const int last = std::min(grid.slices - 1, slice_index((-z + radius) * 1.01, grid) + 1);
      reached *= uint64_t(last - first + 1);
    }
    total += reached;
  }
  return total;
}

}  // namespace pfx_tiledlights
