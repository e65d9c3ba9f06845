#pragma once
// The size of the picture a preset's shaders see (Original, OriginalSize) in a frame of `frame`
// pixels, from the effect's content_width and content_height options. RetroArch shows a console's
// picture (say 320x240) in a larger viewport; pfx hands an effect a whole frame, so by default the
// content is the frame itself, and a video user asks for a console's size instead: the frame is
// then averaged down to it and the shaders draw it over the frame as they would draw a game.
//   both 0:        the frame's size
//   one of them:   the other follows the frame's aspect (rounded, at least 1)
//   both:          as given
// Values are kept within 1..16384.
#include "chain_plan.hpp"

namespace pfx::libretro {

PixelSize content_size(PixelSize frame, int width_option, int height_option);

}  // namespace pfx::libretro
