// The video OBS is started with in the tests: 64x48 RGBA, sRGB, full range, on OBS's OpenGL
// renderer, as OBS Studio would set it up (the size matters little: filters render at their
// source's size).
#pragma once

#include <obs.h>

namespace pfx::test {

inline obs_video_info obs_test_video() {
  obs_video_info video{};
  video.graphics_module = "libobs-opengl";
  video.fps_num = 30;
  video.fps_den = 1;
  video.base_width = video.output_width = 64;
  video.base_height = video.output_height = 48;
  video.output_format = VIDEO_FORMAT_RGBA;
  video.colorspace = VIDEO_CS_SRGB;
  video.range = VIDEO_RANGE_FULL;
  video.scale_type = OBS_SCALE_BILINEAR;
  video.gpu_conversion = true;
  return video;
}

}  // namespace pfx::test
