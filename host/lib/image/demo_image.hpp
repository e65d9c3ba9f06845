// The built-in demo frame (pfx-render --demo) until a real scene exists: a procedural HDR image
// made in code, so the demo and the tests need no files.
//
// What it holds, each placed so an effect's work is easy to see (positions scale with the size):
//   - background: sky-to-ground gradient; depth is 50 m for the sky (top 45 %) and then ramps
//     geometrically to 1 m at the bottom row, like a ground plane seen in perspective;
//   - fine detail: a 1-pixel checker board (near, 1.5 m), a grid of 1-pixel lines (4 m) and a
//     zone plate reaching the pixel Nyquist frequency at its rim (5 m) - blur shows at once;
//     every object is nearer than the background it covers;
//   - three shaded discs at distinct depths (25 m, 8 m, 2.5 m) for depth of field;
//   - bright spots, one pixel wide at their peak: a 1000 "sun" in the sky, spots of 10, 100 and
//     300 on the discs, and a row of seven lamps from 10 to 640 (doubling) across the middle,
//     so a bloom threshold visibly picks some and not others.
// Colour is linear, alpha is 1. The result depends only on the size (no randomness).
#pragma once

#include "image.hpp"

namespace pfx::app {

// width or height <= 0 gives an empty Image (0x0).
Image make_demo_image(int width, int height);

}  // namespace pfx::app
