#include "display_input.hpp"

#include <vector>

#include "png_io.hpp"

namespace pfx::app {

std::unique_ptr<DisplayInput> DisplayInput::create(bool linear_result, std::string* error) {
  std::unique_ptr<DisplayInput> input(new DisplayInput);
  input->linear_result_ = linear_result;
  if (!input->frame_.create(error)) return nullptr;
  return input;
}

bool DisplayInput::load(const std::string& path, Transfer transfer, long long max_pixels, std::string* error) {
  DisplayImage image;
  if (!read_png(path, &image, error, max_pixels)) return false;
  channels_ = image.channels;
  const std::vector<uint8_t> rgba = image.rgba_pixels();
  frame_.resize(image.width, image.height);
  if (linear_result_) frame_.decode_bytes_exact(rgba.data(), transfer);
  else frame_.decode_bytes(rgba.data(), transfer);
  description_ = std::string(image.channels == 4 ? "R, G, B, A" : "R, G, B") + " (8-bit, decoded as " +
                 transfer_name(transfer) + ")";
  return true;
}

DisplayImage DisplayInput::encode_output(Transfer transfer) {
  DisplayImage encoded;
  encoded.width = frame_.width();
  encoded.height = frame_.height();
  encoded.channels = 4;
  encoded.pixels.resize(static_cast<size_t>(encoded.width) * encoded.height * 4);
  frame_.encode_bytes(frame_.output(), transfer, encoded.pixels.data());
  if (channels_ == 3) encoded.drop_alpha();
  return encoded;
}

}  // namespace pfx::app
