// gfx/view_projection.h — the frame's camera matrices in the depth mode in use (no GL).
//
// The camera is the origin of everything sent to the GPU: `view` is its rotation only, and
// positions arrive camera-relative (subtracted in double). The projection is reversed-Z
// (depth 1 at the near plane, 0 at the far one or at infinity) or standard, with a finite or
// infinite far plane; `linearize` turns a depth-buffer value back into view depth for that mode
// (DESIGN.md "Numbers that must stay right": never 1 − depth).
#pragma once
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "gfx/render_view.h"

namespace arc {

struct ViewProjection {
  glm::mat3 camera_basis{1.0f};  // camera to world rotation (columns right, up, back)
  glm::mat4 view{1.0f};          // world to view rotation
  glm::mat4 proj{1.0f};
  glm::mat4 view_proj{1.0f};
  // view depth = x / (depth + y) in every mode, for a window depth in [0, 1]; the particle
  // pass hands it to shaders/particle.frag with the denominator's sign made positive.
  glm::vec2 linearize{0.0f};
  double aspect = 1.0;           // width ÷ height of the scene buffer
};

// The near plane is kept above 1e-6, the far plane beyond the near one and the field of view
// within (0.001, 3.1) radians, so no setting divides by zero.
ViewProjection make_view_projection(const CameraView& camera, double aspect, bool reversed_z, bool infinite_far);

}  // namespace arc
