// gfx/view_projection.cpp — the projection for each depth mode, built in double (no GL).
#include "gfx/view_projection.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace arc {

ViewProjection make_view_projection(const CameraView& cam, double aspect, bool reversed_z, bool infinite_far) {
  ViewProjection vp;
  vp.aspect = aspect;
  double n = std::max(cam.near_plane, 1e-6);
  double f = std::max(cam.far_plane, n * 1.0001);
  double ty = std::tan(std::clamp(cam.fov_y_radians, 1e-3, 3.1) * 0.5);
  glm::dmat4 proj(0.0);
  proj[0][0] = 1.0 / (ty * aspect);
  proj[1][1] = 1.0 / ty;
  proj[2][3] = -1.0;
  if (reversed_z) {
    // depth = A/d + B with depth(n) = 1 and depth(far) = 0; infinite: A = n, B = 0.
    double A = infinite_far ? n : n * f / (f - n);
    double B = infinite_far ? 0.0 : -n / (f - n);
    proj[2][2] = -B;
    proj[3][2] = A;
    vp.linearize = glm::vec2(float(A), float(-B));
  } else if (infinite_far) {
    proj[2][2] = -1.0;
    proj[3][2] = -2.0 * n;
    vp.linearize = glm::vec2(float(-n), -1.0f);  // window depth = 1 − n/d
  } else {
    proj[2][2] = -(f + n) / (f - n);
    proj[3][2] = -2.0 * f * n / (f - n);
    vp.linearize = glm::vec2(float(-n * f / (f - n)), float(-f / (f - n)));
  }
  glm::dmat3 cam_rot = glm::mat3_cast(cam.orientation);
  glm::dmat4 view(glm::transpose(cam_rot));  // rotation only: the camera is the origin
  vp.camera_basis = glm::mat3(cam_rot);
  vp.view = glm::mat4(view);
  vp.proj = glm::mat4(proj);
  vp.view_proj = vp.proj * vp.view;
  return vp;
}

}  // namespace arc
