#include "camera_options.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace pfx::app {

bool parse_camera_options(const std::string& text, CameraOptions* out, std::string* error) {
  CameraOptions options = *out;
  size_t start = 0;
  while (start < text.size()) {
    size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    std::string item = text.substr(start, comma - start);
    start = comma + 1;
    size_t equals = item.find('=');
    if (equals == std::string::npos) {
      *error = "--camera: '" + item + "' is not key=value (keys: fovy, near, far)";
      return false;
    }
    std::string key = item.substr(0, equals), value = item.substr(equals + 1);
    char* end = nullptr;
    double number = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || std::isnan(number)) {
      *error = "--camera: " + key + "='" + value + "' is not a number";
      return false;
    }
    if (key == "fovy") options.fovy_degrees = number;
    else if (key == "near") options.near_plane = number;
    else if (key == "far") options.far_plane = number;
    else {
      *error = "--camera: unknown key '" + key + "' (keys: fovy, near, far)";
      return false;
    }
  }
  const std::string problem = camera_problem(options);
  if (!problem.empty()) {
    *error = "--camera: " + problem;
    return false;
  }
  *out = options;
  return true;
}

std::string camera_problem(const CameraOptions& options) {
  if (!(options.fovy_degrees > 0 && options.fovy_degrees < 180)) return "fovy must be between 0 and 180 degrees";
  if (!(options.near_plane > 0) || std::isinf(options.near_plane)) return "near must be a positive finite distance";
  if (!(options.far_plane > options.near_plane))
    return "far must be greater than near (use far=inf for an infinite projection)";
  return "";
}

pfx_camera make_camera(const CameraOptions& options, int width, int height) {
  pfx_camera camera;
  std::memset(&camera, 0, sizeof camera);
  for (int i = 0; i < 4; ++i) camera.view[i * 5] = 1.0f;
  const double fovy = options.fovy_degrees * M_PI / 180.0;
  const double aspect = double(width) / double(height);
  const double f = 1.0 / std::tan(fovy / 2);
  const double n = options.near_plane, far = options.far_plane;
  float* p = camera.projection;  // column-major
  p[0] = static_cast<float>(f / aspect);
  p[5] = static_cast<float>(f);
  p[11] = -1.0f;
  if (std::isinf(far)) {
    p[10] = -1.0f;
    p[14] = static_cast<float>(-2.0 * n);
  } else {
    p[10] = static_cast<float>(-(far + n) / (far - n));
    p[14] = static_cast<float>(-2.0 * far * n / (far - n));
  }
  camera.near_plane = static_cast<float>(n);
  camera.far_plane = static_cast<float>(far);
  camera.fovy = static_cast<float>(fovy);
  camera.aspect = static_cast<float>(aspect);
  return camera;
}

}  // namespace pfx::app
