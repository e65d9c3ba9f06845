#include "bench_gl_frame.hpp"

#include <algorithm>

#include "display_transfer.hpp"
#include "frame_description.hpp"
#include "image_texture.hpp"

namespace pfx::bench {

bool upload_gl_bench_frame(const BenchFrame& input, const pfx::app::CameraOptions& camera, GlBenchFrame* out,
                           std::string* error) {
  const pfx::app::Image& image = input.image;
  GlBenchFrame& gl = *out;
  const int width = gl.width = image.width, height = gl.height = image.height;
  gl.color = pfx::app::upload_color_texture(image);
  gl.depth = pfx::app::upload_depth_texture(image);
  gl.output = pfx::app::create_color_texture(width, height);
  gl.color_gl = pfx::app::flip_rows(image.rgba, width, height, 4);
  if (!image.depth.empty()) gl.depth_gl = pfx::app::flip_rows(image.depth, width, height, 1);
  if (!input.truth.empty()) gl.truth_gl = pfx::app::flip_rows(input.truth, width, height, 4);
  gl.mask_gl.resize(input.halo_mask.size());
  for (int y = 0; y < height && !gl.mask_gl.empty(); ++y)
    std::copy_n(input.halo_mask.begin() + static_cast<long>(y) * width, width,
                gl.mask_gl.begin() + static_cast<long>(height - 1 - y) * width);

  gl.frame = pfx::app::describe_frame(
      width, height, PFX_INPUT_COLOR | (image.has_depth() ? static_cast<uint32_t>(PFX_INPUT_DEPTH) : 0u),
      PFX_DEPTH_LINEAR, pfx::app::make_camera(camera, width, height));
  gl.textures.color = gl.color;
  gl.textures.depth = gl.depth;
  if (input.display.pixels.empty()) return true;
  gl.display = std::make_unique<pfx::gl::DisplayFrame>();
  if (!gl.display->create(error)) return false;
  gl.display->resize(width, height);
  gl.display->decode_bytes(input.display.pixels.data(), pfx::app::Transfer::SRGB);
  gl.textures.color = gl.display->color();
  return true;
}

std::vector<float> GlBenchFrame::read_result() const {
  if (!display) return pfx::app::flip_rows(pfx::app::download_color_texture(output, width, height).rgba, width, height, 4);
  pfx::app::DisplayImage encoded;
  encoded.width = width;
  encoded.height = height;
  encoded.channels = 4;
  encoded.pixels.resize(static_cast<size_t>(width) * height * 4);
  display->encode_bytes(display->output(), pfx::app::Transfer::SRGB, encoded.pixels.data());  // rows top first
  return pfx::app::flip_rows(pfx::app::decode_display_image(encoded, pfx::app::Transfer::SRGB).rgba, width, height, 4);
}

void release_gl_bench_frame(GlBenchFrame& frame) {
  frame.display.reset();
  pfx::app::delete_texture(frame.color);
  pfx::app::delete_texture(frame.depth);
  pfx::app::delete_texture(frame.output);
}

}  // namespace pfx::bench
