// numpy pictures in and out: float16 or float32, H x W x 4 or H x W x 3, C-contiguous, top row
// first as numpy and image files store them (Image keeps that order; image_texture.hpp flips for
// GL). A result has the input's dtype and channel count. Wrong arrays raise TypeError (dtype) or
// ValueError (shape, layout, a depth of another size) naming the argument.
#pragma once

#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "image.hpp"

namespace pfx::python {

// What the caller's picture looked like, to give the result the same form.
struct PictureForm {
  bool half = false;
  int channels = 4;
};

// The picture (and depth: H x W or H x W x 1, of the picture's size) as an Image: colour as
// float, alpha 1 where the picture has three channels, depth values as given.
app::Image image_from_numpy(const pybind11::array& rgba, const std::optional<pybind11::array>& depth,
                            PictureForm* form);
// The chain's result in the caller's form.
pybind11::array numpy_from_image(const app::Image& image, const PictureForm& form);

}  // namespace pfx::python
