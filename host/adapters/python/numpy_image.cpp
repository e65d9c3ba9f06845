#include "numpy_image.hpp"

#include <cstring>
#include <string>

namespace py = pybind11;

namespace pfx::python {
namespace {

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) text += (i ? ", " : "") + std::to_string(array.shape(i));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// float16 or float32, C-contiguous: anything else is the caller's to convert, said in the message.
void check_layout(const py::array& array, const char* name) {
  const py::dtype dtype = array.dtype();
  if (!dtype.is(py::dtype("float16")) && !dtype.is(py::dtype("float32")))
    throw py::type_error(std::string(name) + " must be float16 or float32, not " + py::str(static_cast<py::handle>(dtype)).cast<std::string>() +
                         ": convert it with .astype(np.float32) (an 8-bit picture divided by 255 first)");
  if (!(array.flags() & py::array::c_style))
    throw py::value_error(std::string(name) + " must be C-contiguous: pass np.ascontiguousarray(" + name + ")");
}

// The array's values as float32, C order (float16 converts exactly).
py::array_t<float, py::array::c_style> as_float32(const py::array& array) {
  return py::array_t<float, py::array::c_style>::ensure(array.attr("astype")("float32"));
}

}  // namespace

app::Image image_from_numpy(const py::array& rgba, const std::optional<py::array>& depth, PictureForm* form) {
  check_layout(rgba, "rgba");
  if (rgba.ndim() != 3 || (rgba.shape(2) != 3 && rgba.shape(2) != 4))
    throw py::value_error("rgba must be H x W x 4 or H x W x 3, not shape " + shape_text(rgba));
  if (rgba.shape(0) < 1 || rgba.shape(1) < 1) throw py::value_error("rgba is empty: shape " + shape_text(rgba));
  form->half = rgba.dtype().is(py::dtype("float16"));
  form->channels = static_cast<int>(rgba.shape(2));

  app::Image image;
  image.height = static_cast<int>(rgba.shape(0));
  image.width = static_cast<int>(rgba.shape(1));
  const auto colour = as_float32(rgba);
  const float* in = colour.data();
  image.rgba.resize(image.pixel_count() * 4);
  for (size_t pixel = 0; pixel < image.pixel_count(); ++pixel) {
    std::memcpy(&image.rgba[pixel * 4], in + pixel * form->channels, sizeof(float) * form->channels);
    if (form->channels == 3) image.rgba[pixel * 4 + 3] = 1.0f;
  }
  if (depth) {
    check_layout(*depth, "depth");
    const bool matches = (depth->ndim() == 2 || (depth->ndim() == 3 && depth->shape(2) == 1)) &&
                         depth->shape(0) == image.height && depth->shape(1) == image.width;
    if (!matches)
      throw py::value_error("depth must be H x W (" + std::to_string(image.height) + " x " + std::to_string(image.width) +
                            ", the picture's size), not shape " + shape_text(*depth));
    const auto values = as_float32(*depth);
    image.depth.assign(values.data(), values.data() + image.pixel_count());
  }
  return image;
}

py::array numpy_from_image(const app::Image& image, const PictureForm& form) {
  py::array_t<float, py::array::c_style> out({image.height, image.width, form.channels});
  float* data = out.mutable_data();
  for (size_t pixel = 0; pixel < image.pixel_count(); ++pixel)
    std::memcpy(data + pixel * form.channels, &image.rgba[pixel * 4], sizeof(float) * form.channels);
  // The chain's output is half floats: float16 holds each value exactly.
  if (form.half) return out.attr("astype")("float16");
  return std::move(out);
}

}  // namespace pfx::python
