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

// The picture's size and depth (H x W or H x W x 1, of the picture's size, the values as given) as
// an Image, and its form; the colour is not read yet.
app::Image picture_frame(const pybind11::array& rgba, const std::optional<pybind11::array>& depth, PictureForm* form);
// A uint8 picture's colour as tightly packed RGBA bytes, alpha 255 where it has three channels.
void read_picture_bytes(const pybind11::array& rgba, const PictureForm& form, std::vector<uint8_t>* bytes);
// A float picture on its way through the chain: its colour as float32 (the caller's array itself
// when it is float32 already) and a new float32 array of its shape for the result.
struct FloatPicture {
  pybind11::array_t<float, pybind11::array::c_style> colour, result;
};
FloatPicture float_picture(const pybind11::array& rgba);
// The result in the caller's dtype.
pybind11::array float_result(FloatPicture& picture, const PictureForm& form);
// What a chain that runs no pass gives back, in one pass over the picture and with no GL: a new
// array of its dtype and shape holding bytes and half floats as they came, and float32 values at
// the precision of the chain's colour (rounded to half floats, round_to_half). With the GIL held.
pybind11::array unchanged_picture(const pybind11::array& rgba, const PictureForm& form);
// A display-referred picture's result (RGBA bytes, width x height) in the caller's channel count.
pybind11::array numpy_from_bytes(const std::vector<uint8_t>& bytes, int width, int height, const PictureForm& form);

}  // namespace pfx::python
