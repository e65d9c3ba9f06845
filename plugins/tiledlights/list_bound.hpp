// An upper bound, computed on the CPU before the GPU builds its lists, of how many light indices
// the `tiled` or `clustered` lists of a frame can hold in all. The GPU counts the exact number, but
// only the GPU knows it; the bound lets the index buffer be sized for the frame without waiting
// for the GPU. For each light: the screen tiles whose side planes its (widened) sphere passes, times
// (clusters) the depth slices its depth range meets. The GPU also cuts by the tiles' depth bounds,
// which the bound ignores, so it is loose; it never falls short. GL-free.
#pragma once

#include <cstdint>
#include <vector>

#include "light_set.hpp"
#include "view_frustum.hpp"

namespace pfx_tiledlights {

struct ListGrid {
  int width = 0, height = 0;  // frame pixels
  int tile_size = 16;         // pixels per tile side (the last column and row may be cut)
  int slices = 0;             // 0: tiles only; otherwise exponential depth slices
  double slice_near = 0.1;    // the near depth of slicing
  double slice_far = 100;     // the far depth of slicing (finite)
};

// Extra radius over each light's culling radius, relative and absolute (x (1 + |centre|)): far more
// than the GPU's float rounding of planes and centres (a few 1e-7 of the distances involved).
constexpr double kBoundRelativeMargin = 1e-3;
constexpr double kBoundAbsoluteMargin = 1e-3;

// Sum over the lights `visible` (indices into set.lights) of the tiles (x slices) each may reach.
uint64_t list_entries_bound(const LightSet& set, const std::vector<uint32_t>& visible, const Perspective& perspective,
                            const ListGrid& grid);

}  // namespace pfx_tiledlights
