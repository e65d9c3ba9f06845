// The camera moves of the viewer, as plain functions on the scene camera so they can be tested
// without a window: orbit around the target, pan, zoom toward the target, fly (camera and target
// move together), and framing a box. The camera's `up` is the axis of orbiting and is kept.
#pragma once

#include <glm/vec3.hpp>

#include "scene.hpp"

namespace pfx::app {

// Turns the camera around its target: yaw about `up`, then pitch about the camera's right axis.
// Pitch stops 1 degree short of the poles (looking straight along `up` has no defined right).
// The distance to the target is kept.
void orbit_camera(Camera* camera, double yaw_radians, double pitch_radians);

// Moves camera and target in the view plane so the point at the target's depth follows a mouse
// drag of (dx, dy) pixels (x to the right, y down) in a viewport viewport_height pixels high.
void pan_camera(Camera* camera, double dx_pixels, double dy_pixels, int viewport_height);

// Moves the camera toward (steps > 0) or away from the target: the distance is multiplied by
// 0.85^steps and kept above 1 mm. The direction is kept.
void zoom_camera(Camera* camera, double steps);

// Moves camera and target together by the given metres along the camera's own axes: right,
// up (the camera's `up`), forward (the view direction).
void fly_camera(Camera* camera, const glm::dvec3& right_up_forward_metres);

// Keeps the view direction and aims at the box's centre from the distance at which its bounding
// sphere fits the narrower field of view of a frame of this aspect (width / height). A finite far
// plane closer than the far side of the sphere is moved out to twice that distance; an empty box
// (lo == hi) is framed as a sphere of 1 m.
void frame_box(Camera* camera, const glm::dvec3& lo, const glm::dvec3& hi, double aspect);

}  // namespace pfx::app
