// The camera our command-line programs put in pfx_frame: at the origin looking down -Z, with a
// standard OpenGL perspective projection built from "fovy=45,near=0.1,far=1000" (degrees, metres;
// far may be "inf").
#pragma once

#include <string>

#include <pfx/effect.h>

namespace pfx::app {

struct CameraOptions {
  double fovy_degrees = 45;
  double near_plane = 0.1;
  double far_plane = 1000;
};

// Parses "fovy=45,near=0.1,far=1000" (any subset, any order). False with *error naming the key.
bool parse_camera_options(const std::string& text, CameraOptions* out, std::string* error);
// What is wrong with the lens ("near must be a positive finite distance"), or "" when nothing is.
std::string camera_problem(const CameraOptions& options);
pfx_camera make_camera(const CameraOptions& options, int width, int height);

}  // namespace pfx::app
