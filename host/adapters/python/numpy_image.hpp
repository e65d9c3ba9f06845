// numpy pictures in and out: uint8, float16 or float32, H x W x 4 or H x W x 3, C-contiguous, top
// row first as numpy and image files store them (Image keeps that order; image_texture.hpp flips
// for GL). uint8 pictures are display-referred (what PIL, imageio and OpenCV hand out) and stay
// bytes: the GL decodes and encodes them as pfx-render does an 8-bit PNG. A result has the
// input's dtype and channel count. Wrong arrays raise TypeError (dtype) or ValueError (shape,
// layout, a depth of another size) naming the argument.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "image.hpp"

namespace pfx::python {

// What the caller's picture looked like, to give the result the same form.
struct PictureForm {
  bool half = false;
  bool bytes = false;  // uint8: display-referred
  int channels = 4;
};

// The picture (and depth: H x W or H x W x 1, of the picture's size) as an Image: its size, the
// depth values as given, and the colour as float in image.rgba, or for a uint8 picture as
// tightly packed RGBA bytes in *bytes (image.rgba left empty); alpha is opaque (1.0, 255) where
// the picture has three channels.
app::Image image_from_numpy(const pybind11::array& rgba, const std::optional<pybind11::array>& depth,
                            PictureForm* form, std::vector<uint8_t>* bytes);
// The chain's result in the caller's form: from image.rgba, or for a uint8 picture from `bytes`
// (RGBA, the image's size).
pybind11::array numpy_from_image(const app::Image& image, const std::vector<uint8_t>& bytes, const PictureForm& form);

}  // namespace pfx::python
