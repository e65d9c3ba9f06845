// The pictures the OBS tests feed sources with, cut from a real photograph Debian ships, and
// comparing what OBS gives back with pfx-render's files.
#pragma once

#include <string>
#include <vector>

#include "image.hpp"
#include "obs_session.hpp"

namespace pfx::test {

// width x height pixels of a photograph (by default the tests' own) from (x, y), written to `path` as an RGB PNG; with
// `alpha`, an RGBA PNG whose alpha falls from 255 at the left to 0 at the right.
app::DisplayImage write_photo_crop(const std::string& path, int x, int y, int width, int height, bool alpha = false,
                                   const std::string& photograph = PFX_TEST_PHOTOGRAPH);
// A PNG as RGBA (alpha 255 where it has none); REQUIREs that it reads.
app::DisplayImage read_picture(const std::string& path);
// The largest difference of any channel (RGB, or RGBA with `with_alpha`) between a frame and a
// picture of the same size; REQUIREs the sizes match.
int worst_difference(const ObsFrame& frame, const app::DisplayImage& picture, bool with_alpha = true);
// The same between two pictures of one size (RGBA).
int worst_difference_pictures(const app::DisplayImage& a, const app::DisplayImage& b);
// pfx-render --input `input` --chain `chain` --set each of `sets` to `output`, the shipped plugins only;
// REQUIREs that it succeeds, and returns the picture.
app::DisplayImage pfx_render_picture(const std::string& input, const std::string& chain,
                                     const std::vector<std::string>& sets,
                                     const std::string& output);

}  // namespace pfx::test
