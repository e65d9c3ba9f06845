// Ground truth for depth of field (the ray-traced reference of docs/effects/dof.md): a small
// synthetic 3D scene of planes, boxes and bright spheres at known distances, rendered by casting
// rays in double precision.
//
// The pinhole frame (colour and linear depth) is what an engine would hand the effect: colour
// averaged over the pixel's square (4 x 4 points), depth and object of the nearest of them. The truth is
// the same scene through a thin lens: every pixel averages rays from points spread over the lens
// aperture to the point where the pixel's pinhole ray meets the plane in focus, which is what
// rendering the scene once per lens point with the projection sheared to keep that plane fixed, and
// averaging, gives. It has the true partial occlusion that no post effect can recover from one
// pinhole frame: a blurred foreground's edge shows the background hidden behind it.
//
// For a point at depth D the rays of a lens of aperture A focused at P spread over a disc of
// diameter A |D - P| / D on the plane in focus, which in pixels is exactly the CoC of dof_camera.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/effect.h>

namespace pfx_dof {

// Object ids in SceneFrame::object.
enum SceneObject : uint8_t {
  OBJECT_NONE = 0,
  OBJECT_WALL,
  OBJECT_GROUND,
  OBJECT_SUBJECT,  // the sharp object: a bright box at the scene's focus distance
  OBJECT_NEAR_BOX,
  OBJECT_FAR_BOX,
  OBJECT_LIGHT,    // small bright spheres
};

// The distance the scene is built around: the subject's front face.
constexpr double kSceneFocusDistance = 5.0;

struct SceneFrame {
  int width = 0, height = 0;
  std::vector<float> rgba;            // rows bottom first
  std::vector<float> depth;           // linear view depth, metres
  std::vector<uint8_t> object;        // what the pinhole ray hit
};

// The camera of frame (fovy, aspect) at the origin looking down -Z; depth encoding linear.
SceneFrame render_pinhole(const pfx_frame& frame);

// The thin-lens truth: aperture diameter and focus distance in metres (dof_camera's Lens), lens
// samples per pixel (rounded up to a square of a multiple of 4; stratified over the disc, turned
// per pixel so bokeh shows noise rather than copies of one pattern, and paired with the pinhole's
// 16 points in the pixel's square), seed for that turn. Uses every hardware thread.
std::vector<float> render_lens_truth(const pfx_frame& frame, double aperture_m, double focus_distance_m,
                                     int lens_samples, uint64_t seed = 1);

}  // namespace pfx_dof
