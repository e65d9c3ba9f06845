// Tiled shading's culling (Olsson and Assarsson) on the CPU, at any resolution: the view frustum split into a grid of
// sub-frustums (8x4 by default), each light's sphere tested against their side planes, and one
// list of light indices per sub-frustum. Lists have no fixed size (one flat index array with an
// offset and a count per tile), so nothing is ever truncated. GL-free.
#pragma once

#include <cstdint>
#include <vector>

#include "light_set.hpp"
#include "view_frustum.hpp"

namespace pfx_tiledlights {

struct ListStats {
  uint64_t lists = 0;         // tiles or clusters
  uint64_t entries = 0;       // indices over all lists
  uint32_t max_length = 0;
  uint32_t inconsistent = 0;  // GPU lists whose fill disagreed with their count (never, short of a bug)
  double mean_length() const { return lists ? double(entries) / double(lists) : 0.0; }
};

struct GridLists {
  int tiles_x = 0, tiles_y = 0;
  std::vector<uint32_t> heads;    // per tile (row-major from the bottom): offset, count
  std::vector<uint32_t> indices;  // into the light set, increasing within each list
  ListStats stats;
};

// Lights of the set whose sphere reaches the view frustum between near and far (the main
// frustum test), in order: the lights a culled mode uploads.
std::vector<uint32_t> lights_in_view(const LightSet& set, const Perspective& perspective, int width, int height,
                                     double near_depth, double far_depth);

// The per-tile lists of a tiles_x x tiles_y grid over a width x height frame, for the lights
// `candidates` (indices into set.lights); the lists hold positions in `candidates`. False when the
// lists would hold more than 2^32 - 1 indices in all (32-bit offsets).
bool cull_grid(const LightSet& set, const std::vector<uint32_t>& candidates, const Perspective& perspective,
               int width, int height, int tiles_x, int tiles_y, GridLists* out);

}  // namespace pfx_tiledlights
