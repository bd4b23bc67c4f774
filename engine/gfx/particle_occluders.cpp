// gfx/particle_occluders.cpp — mesh part boxes projected for the soft-edge reach test (no GL).
#include "gfx/particle_occluders.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace arc {
namespace {

// A model-space box under the instance's camera-relative transform as an Occluder; false when
// it lies wholly in front of the near plane or off the screen (tangent half-extents mx, my).
bool project_box(const Box3& box, const glm::dvec3& rel, const glm::dmat3& rot, const glm::mat3& to_view, float near,
                 float mx, float my, Occluder& o) {
  const float inf = std::numeric_limits<float>::infinity();
  o = Occluder::none();
  bool crosses_near = false;
  for (int i = 0; i < 8; ++i) {
    glm::dvec3 corner((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y, (i & 4) ? box.hi.z : box.lo.z);
    glm::vec3 c = to_view * glm::vec3(rel + rot * corner);
    float d = -c.z;
    o.nearest = std::min(o.nearest, d);
    o.farthest = std::max(o.farthest, d);
    if (d <= near) {
      crosses_near = true;
      continue;
    }
    o.x0 = std::min(o.x0, c.x / d);
    o.x1 = std::max(o.x1, c.x / d);
    o.y0 = std::min(o.y0, c.y / d);
    o.y1 = std::max(o.y1, c.y / d);
  }
  if (!(o.farthest > near)) return false;  // wholly in front of the near plane: it draws nothing
  if (crosses_near) o.x0 = o.y0 = -inf, o.x1 = o.y1 = inf;
  // Only what is on screen can stand behind a particle's pixels.
  if (o.x0 > mx || o.x1 < -mx || o.y0 > my || o.y1 < -my) return false;
  o.x0 = std::max(o.x0, -mx), o.x1 = std::min(o.x1, mx);
  o.y0 = std::max(o.y0, -my), o.y1 = std::min(o.y1, my);
  // Float transforms on the GPU differ from these in the last bits: widen a little.
  o.nearest -= 1e-4f * std::abs(o.nearest) + 1e-5f;
  o.farthest += 1e-4f * std::abs(o.farthest) + 1e-5f;
  return true;
}

}  // namespace

QuadBounds quad_bounds(const ParticleInstance& p, const glm::mat3& to_view, float axis_len) {
  QuadBounds b;
  b.centre = to_view * glm::vec3(p.pos[0], p.pos[1], p.pos[2]);
  b.size = std::max(p.size, 1e-6f);
  b.axis_locked = p.billboard == uint8_t(Billboard::AxisLocked);
  b.half_long = b.axis_locked ? 0.5f * axis_len + b.size : b.size;
  b.radius = std::sqrt(b.size * b.size + b.half_long * b.half_long) * 1.001f;
  return b;
}

Occluder Occluder::none() {
  const float inf = std::numeric_limits<float>::infinity();
  return Occluder{inf, -inf, inf, inf, -inf, -inf};
}

void Occluder::include(const Occluder& o) {
  nearest = std::min(nearest, o.nearest), farthest = std::max(farthest, o.farthest);
  x0 = std::min(x0, o.x0), x1 = std::max(x1, o.x1);
  y0 = std::min(y0, o.y0), y1 = std::max(y1, o.y1);
}

void OccluderSet::gather(const RenderView& v, const ModelCoverBoxes& model_boxes, const glm::mat3& to_view, float tan_x,
                         float tan_y) {
  occluders_.clear();
  groups_.clear();
  const float near = float(v.camera.near_plane);
  const float mx = tan_x * 1.01f, my = tan_y * 1.01f;
  bounds_ = Occluder::none();
  for (const MeshInstance& inst : v.meshes) {
    if (!inst.model || inst.model.index() >= model_boxes.size()) continue;
    // The same camera-relative transform the mesh pass uses, taken in double before float.
    const glm::dvec3 rel = inst.position - v.camera.position;
    const glm::dmat3 rot = glm::mat3_cast(inst.orientation) * inst.scale;
    OccluderGroup group{Occluder::none(), occluders_.size(), 0};
    Occluder o;
    for (const Box3& part : model_boxes[inst.model.index()]) {
      if (!project_box(part, rel, rot, to_view, near, mx, my, o)) continue;
      occluders_.push_back(o);
      group.bound.include(o);
      ++group.count;
    }
    if (group.count == 0) continue;
    groups_.push_back(group);
    bounds_.include(group.bound);
  }
}

// Whether an opaque surface can lie, at some pixel of the particle's quad, less than its depth
// extent E behind the quad, or between the quad and where the density methods push it (E/2 for
// average density, E for density extent, towards the camera). Behind that range every method
// gives exactly 1 (linear and contrast reach 1 at zb − z ≥ E, average density at E/2, density
// extent at E·texture alpha); in front of it the depth test rejects the fragment whatever the
// factor. When no mesh box reaches into the range, the particle can skip the depth read and
// stay bit-identical. With the bounds of QuadBounds: a camera-facing quad is built from
// view-space axes, so it lies at one view depth; an axis-locked quad lies in the plane through
// its centre square to the view ray, so its view depth varies by at most its radius times the
// sine of the ray's angle to the view axis.
bool OccluderSet::soft_can_matter(const ParticleInstance& p, const QuadBounds& q, float near) const {
  const glm::vec3& c = q.centre;
  float d = -c.z;
  float extent = p.soft_extent > 0.0f ? p.soft_extent : q.size;
  float dist = glm::length(c);
  float sine = dist > 0.0f ? std::sqrt(std::max(0.0f, 1.0f - (c.z / dist) * (c.z / dist))) : 1.0f;
  float spread = q.axis_locked ? q.radius * std::min(1.0f, sine + 1e-4f) : 0.0f;
  float reach = d + spread + extent * 1.001f;
  uint8_t method = p.soft_edge & ~kSoftClear;
  float push = method == uint8_t(SoftEdge::AverageDensity) ? 0.5f * extent
               : method == uint8_t(SoftEdge::DensityExtent) ? extent
                                                           : 0.0f;
  float front = d - spread - push * 1.001f;
  float z0 = d - spread, z1 = d + spread;
  bool whole_screen = !(z0 > near);
  // The quad's footprint in tangent units; pushing it along the view ray (density methods)
  // keeps the footprint.
  auto lo = [&](float a) { return a < 0.0f ? a / z0 : a / z1; };
  auto hi = [&](float b) { return b < 0.0f ? b / z1 : b / z0; };
  float x0 = whole_screen ? 0.0f : lo(c.x - q.radius), x1 = whole_screen ? 0.0f : hi(c.x + q.radius);
  float y0 = whole_screen ? 0.0f : lo(c.y - q.radius), y1 = whole_screen ? 0.0f : hi(c.y + q.radius);
  auto touches = [&](const Occluder& o) {
    return o.nearest < reach && o.farthest > front &&
           (whole_screen || (o.x0 <= x1 && x0 <= o.x1 && o.y0 <= y1 && y0 <= o.y1));
  };
  if (groups_.empty() || !touches(bounds_)) return false;
  for (const OccluderGroup& g : groups_) {
    if (!touches(g.bound)) continue;
    for (size_t i = g.first; i < g.first + g.count; ++i)
      if (touches(occluders_[i])) return true;
  }
  return false;
}

}  // namespace arc
