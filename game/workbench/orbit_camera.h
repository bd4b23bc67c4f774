// game/workbench/orbit_camera.h — the workbench's camera: it circles a target point.
//
// Yaw and pitch turn the eye around the target at a distance; dragging changes the angles,
// the wheel scales the distance, and frame() fits a sphere in the view. Pitch stops short of
// the poles, so the view direction is never parallel to the up vector.
//
// Example, compiled as AppExamples.OrbitCamera in tests/unit/app/test_app_examples.cpp:
//   OrbitCamera cam;
//   cam.drag(dx_pixels, dy_pixels);
//   cam.zoom(wheel_steps);
//   cam.frame(centre, radius);
//   CameraView v = cam.view();
#pragma once
#include <glm/vec3.hpp>

#include "gfx/render_view.h"

namespace arc {

class OrbitCamera {
 public:
  void drag(double dx_pixels, double dy_pixels);  // 0.3° per pixel
  void zoom(double wheel_steps);                  // each step 20% closer (positive) or farther
  void frame(const glm::dvec3& centre, double radius);
  CameraView view() const;

  glm::dvec3 target{0.0};
  double yaw = 0.5;        // radians around +Y; 0 looks along −Z
  double pitch = -0.3;     // radians; negative looks down
  double distance = 30.0;  // m
  double fov_y = 0.9;      // radians
};

}  // namespace arc
