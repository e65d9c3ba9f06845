// pfx-render's 8-bit input: a PNG (a frame a video tool wrote, a photograph) is display-referred,
// so it is decoded to linear light on the GPU and the result encoded back, by the same code and
// --transfer setting as the frei0r plugins and the GStreamer element (display_frame.hpp): a frame
// those hosts filtered can be compared with pfx-render byte for byte.
#pragma once

#include <memory>
#include <string>

#include "display_frame.hpp"
#include "display_transfer.hpp"
#include "image.hpp"

namespace pfx::app {

class DisplayInput {
 public:
  // The programs and framebuffers; the context must be current. Null with *error. With
  // linear_result the result is wanted in linear light at full precision (an EXR is written): the
  // frame is then decoded exactly into RGBA16F, rendered into RGBA16F and encoded back from it,
  // where otherwise it stays 8-bit through the chain as in every host of 8-bit frames
  // (display_frame.hpp); the two give PNGs within a code of each other.
  static std::unique_ptr<DisplayInput> create(bool linear_result, std::string* error);
  bool linear_result() const { return linear_result_; }

  // Reads the PNG (RGB, RGBA, grey; 16-bit files are reduced to 8 bits) and decodes it into
  // color(). False with *error "PATH: reason".
  bool load(const std::string& path, Transfer transfer, long long max_pixels, std::string* error);
  int width() const { return frame_.width(); }
  int height() const { return frame_.height(); }
  // What load read, for the log and the JSON report ("R, G, B, A (8-bit sRGB)").
  const std::string& description() const { return description_; }

  uint32_t color() const { return frame_.color(); }
  // The texture to render the chain into, and that texture encoded back to 8 bits with the
  // input's channels (RGB or RGBA).
  uint32_t output() const { return frame_.output(); }
  DisplayImage encode_output(Transfer transfer);

 private:
  gl::DisplayFrame frame_;
  int channels_ = 4;
  bool linear_result_ = false;
  std::string description_;
};

}  // namespace pfx::app
