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

// float16 or float32 (or uint8 where bytes are taken), C-contiguous: anything else is the caller's
// to convert, said in the message.
void check_layout(const py::array& array, const char* name, bool takes_bytes) {
  const py::dtype dtype = array.dtype();
  const bool is_float = dtype.is(py::dtype("float16")) || dtype.is(py::dtype("float32"));
  if (!is_float && !(takes_bytes && dtype.is(py::dtype("uint8")))) {
    const std::string got = py::str(static_cast<py::handle>(dtype)).cast<std::string>();
    if (takes_bytes)
      throw py::type_error(std::string(name) + " must be uint8 (display-referred), float16 or float32 (linear), not " +
                           got + ": convert it with .astype(np.float32)");
    throw py::type_error(std::string(name) + " must be float16 or float32, not " + got +
                         ": convert it with .astype(np.float32)");
  }
  if (!(array.flags() & py::array::c_style))
    throw py::value_error(std::string(name) + " must be C-contiguous: pass np.ascontiguousarray(" + name + ")");
}

// The array's values as float32, C order (float16 converts exactly).
py::array_t<float, py::array::c_style> as_float32(const py::array& array) {
  return py::array_t<float, py::array::c_style>::ensure(array.attr("astype")("float32"));
}

// Interleaved pixels of `channels` values to RGBA, alpha `opaque` where there are three.
template <typename T>
void expand_to_rgba(const T* in, size_t pixels, int channels, T opaque, T* out) {
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    std::memcpy(out + pixel * 4, in + pixel * channels, sizeof(T) * channels);
    if (channels == 3) out[pixel * 4 + 3] = opaque;
  }
}

// RGBA to interleaved pixels of `channels` values (alpha dropped where there are three).
template <typename T>
void narrow_from_rgba(const T* in, size_t pixels, int channels, T* out) {
  for (size_t pixel = 0; pixel < pixels; ++pixel) std::memcpy(out + pixel * channels, in + pixel * 4, sizeof(T) * channels);
}

}  // namespace

app::Image image_from_numpy(const py::array& rgba, const std::optional<py::array>& depth, PictureForm* form,
                            std::vector<uint8_t>* bytes) {
  check_layout(rgba, "rgba", true);
  if (rgba.ndim() != 3 || (rgba.shape(2) != 3 && rgba.shape(2) != 4))
    throw py::value_error("rgba must be H x W x 4 or H x W x 3, not shape " + shape_text(rgba));
  if (rgba.shape(0) < 1 || rgba.shape(1) < 1) throw py::value_error("rgba is empty: shape " + shape_text(rgba));
  form->half = rgba.dtype().is(py::dtype("float16"));
  form->bytes = rgba.dtype().is(py::dtype("uint8"));
  form->channels = static_cast<int>(rgba.shape(2));

  app::Image image;
  image.height = static_cast<int>(rgba.shape(0));
  image.width = static_cast<int>(rgba.shape(1));
  if (form->bytes) {
    bytes->resize(image.pixel_count() * 4);
    expand_to_rgba(static_cast<const uint8_t*>(rgba.data()), image.pixel_count(), form->channels, uint8_t{255},
                   bytes->data());
  } else {
    const auto colour = as_float32(rgba);
    image.rgba.resize(image.pixel_count() * 4);
    expand_to_rgba(colour.data(), image.pixel_count(), form->channels, 1.0f, image.rgba.data());
  }
  if (depth) {
    check_layout(*depth, "depth", false);
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

py::array numpy_from_image(const app::Image& image, const std::vector<uint8_t>& bytes, const PictureForm& form) {
  if (form.bytes) {
    py::array_t<uint8_t, py::array::c_style> out({image.height, image.width, form.channels});
    narrow_from_rgba(bytes.data(), image.pixel_count(), form.channels, out.mutable_data());
    return std::move(out);
  }
  py::array_t<float, py::array::c_style> out({image.height, image.width, form.channels});
  narrow_from_rgba(image.rgba.data(), image.pixel_count(), form.channels, out.mutable_data());
  // The chain's output is half floats: float16 holds each value exactly.
  if (form.half) return out.attr("astype")("float16");
  return std::move(out);
}

}  // namespace pfx::python
