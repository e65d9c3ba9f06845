#include "numpy_image.hpp"

#include <cstring>
#include <string>

#include "half_rounding.hpp"

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

// The array's values as float32, C order (float16 converts exactly); float32 as it is, uncopied.
py::array_t<float, py::array::c_style> as_float32(const py::array& array) {
  return py::array_t<float, py::array::c_style>::ensure(array);
}

// Interleaved pixels of `channels` values to RGBA, alpha `opaque` where there are three.
template <typename T>
void expand_to_rgba(const T* in, size_t pixels, int channels, T opaque, T* out) {
  if (channels == 4) {
    std::memcpy(out, in, sizeof(T) * 4 * pixels);
    return;
  }
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    std::memcpy(out + pixel * 4, in + pixel * channels, sizeof(T) * channels);
    if (channels == 3) out[pixel * 4 + 3] = opaque;
  }
}

// RGBA to interleaved pixels of `channels` values (alpha dropped where there are three).
template <typename T>
void narrow_from_rgba(const T* in, size_t pixels, int channels, T* out) {
  if (channels == 4) {
    std::memcpy(out, in, sizeof(T) * 4 * pixels);
    return;
  }
  for (size_t pixel = 0; pixel < pixels; ++pixel) std::memcpy(out + pixel * channels, in + pixel * 4, sizeof(T) * channels);
}

}  // namespace

app::Image picture_frame(const py::array& rgba, const std::optional<py::array>& depth, PictureForm* form) {
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

void read_picture_bytes(const py::array& rgba, const PictureForm& form, std::vector<uint8_t>* bytes) {
  const size_t pixels = static_cast<size_t>(rgba.shape(0)) * static_cast<size_t>(rgba.shape(1));
  bytes->resize(pixels * 4);
  expand_to_rgba(static_cast<const uint8_t*>(rgba.data()), pixels, form.channels, uint8_t{255}, bytes->data());
}

FloatPicture float_picture(const py::array& rgba) {
  FloatPicture picture;
  picture.colour = as_float32(rgba);
  picture.result = py::array_t<float, py::array::c_style>(std::vector<py::ssize_t>(rgba.shape(), rgba.shape() + rgba.ndim()));
  return picture;
}

py::array float_result(FloatPicture& picture, const PictureForm& form) {
  // The chain's output is half floats: float16 holds each value exactly.
  if (form.half) return picture.result.attr("astype")("float16");
  return std::move(picture.result);
}

py::array unchanged_picture(const py::array& rgba, const PictureForm& form) {
  // Bytes and half floats are what the chain would give back as they are.
  if (form.bytes || form.half) return rgba.attr("copy")();
  py::array_t<float, py::array::c_style> out(std::vector<py::ssize_t>(rgba.shape(), rgba.shape() + rgba.ndim()));
  const float* in = static_cast<const float*>(rgba.data());
  float* values = out.mutable_data();
  const size_t count = static_cast<size_t>(out.size());
  {
    py::gil_scoped_release release;  // the caller keeps both arrays alive
    for (size_t i = 0; i < count; ++i) values[i] = app::round_to_half(in[i]);
  }
  return std::move(out);
}

py::array numpy_from_bytes(const std::vector<uint8_t>& bytes, int width, int height, const PictureForm& form) {
  py::array_t<uint8_t, py::array::c_style> out({height, width, form.channels});
  narrow_from_rgba(bytes.data(), static_cast<size_t>(width) * height, form.channels, out.mutable_data());
  return std::move(out);
}

}  // namespace pfx::python
