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

// The part box's slabs in view space, under the same transform as project_box.
ViewBox view_box(const Box3& box, const glm::dvec3& rel, const glm::dmat3& rot, const glm::mat3& to_view) {
  const glm::dvec3 mid = (glm::dvec3(box.lo) + glm::dvec3(box.hi)) * 0.5;
  const glm::dvec3 half = (glm::dvec3(box.hi) - glm::dvec3(box.lo)) * 0.5;
  const glm::vec3 centre = to_view * glm::vec3(rel + rot * mid);
  glm::vec3 edge[3];
  for (int i = 0; i < 3; ++i) edge[i] = to_view * glm::vec3(rot[i] * half[i]);
  ViewBox b;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 n = glm::cross(edge[(i + 1) % 3], edge[(i + 2) % 3]);
    const float len = glm::length(n);
    b.normal[i] = len > 0.0f ? n / len : glm::vec3(0.0f);
    b.middle[i] = glm::dot(centre, b.normal[i]);
    // The other two edges lie in the slab's plane; only edge i reaches across it.
    const float width = std::abs(glm::dot(edge[i], b.normal[i]));
    b.half_width[i] = width + 1e-4f * (glm::length(centre) + width) + 1e-5f;
  }
  return b;
}

// Whether one face slab of `b` has all eight corners of a reach volume on one side.
bool separated(const ViewBox& b, const glm::vec3 (&corners)[8]) {
  for (int i = 0; i < 3; ++i) {
    bool above = true, below = true;
    for (int k = 0; k < 8 && (above || below); ++k) {
      const float s = glm::dot(corners[k], b.normal[i]) - b.middle[i];
      above = above && s > b.half_width[i];
      below = below && s < -b.half_width[i];
    }
    if (above || below) return true;
  }
  return false;
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

QuadFootprint quad_footprint(const QuadBounds& q, float near) {
  const glm::vec3& c = q.centre;
  const float d = -c.z;
  float spread = 0.0f;
  if (q.axis_locked) {
    const float dist = glm::length(c);
    const float sine = dist > 0.0f ? std::sqrt(std::max(0.0f, 1.0f - (c.z / dist) * (c.z / dist))) : 1.0f;
    spread = q.radius * std::min(1.0f, sine + 1e-4f);
  }
  QuadFootprint f;
  f.z0 = d - spread, f.z1 = d + spread;
  f.whole_screen = !(f.z0 > near);
  if (f.whole_screen) {
    f.x0 = f.y0 = f.x1 = f.y1 = 0.0f;
    return f;
  }
  // A side's extreme tangent is at the nearest depth when it lies that way from the axis.
  auto lo = [&](float a) { return a < 0.0f ? a / f.z0 : a / f.z1; };
  auto hi = [&](float b) { return b < 0.0f ? b / f.z1 : b / f.z0; };
  f.x0 = lo(c.x - q.radius), f.x1 = hi(c.x + q.radius);
  f.y0 = lo(c.y - q.radius), f.y1 = hi(c.y + q.radius);
  return f;
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
  boxes_.clear();
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
      boxes_.push_back(view_box(part, rel, rot, to_view));
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
// stay bit-identical. The quad's depths and footprint are those of quad_footprint().
bool OccluderSet::soft_can_matter(const ParticleInstance& p, const QuadBounds& q, float near) const {
  const QuadFootprint f = quad_footprint(q, near);
  float extent = p.soft_extent > 0.0f ? p.soft_extent : q.size;
  uint8_t method = p.soft_edge & ~kSoftClear;
  float push = method == uint8_t(SoftEdge::AverageDensity) ? 0.5f * extent
               : method == uint8_t(SoftEdge::DensityExtent) ? extent
                                                           : 0.0f;
  return reach_can_matter(f, extent, push, near);
}

QuadFootprint sphere_footprint(const glm::vec3& centre, float radius, float near) {
  QuadBounds q{centre, radius, radius, radius, false};
  QuadFootprint f = quad_footprint(q, near);  // x/y at the centre's depth; now spread in depth
  f.z0 = -centre.z - radius, f.z1 = -centre.z + radius;
  f.whole_screen = !(f.z0 > near);
  if (f.whole_screen) return f;
  auto lo = [&](float a) { return a < 0.0f ? a / f.z0 : a / f.z1; };
  auto hi = [&](float b) { return b < 0.0f ? b / f.z1 : b / f.z0; };
  f.x0 = lo(centre.x - radius), f.x1 = hi(centre.x + radius);
  f.y0 = lo(centre.y - radius), f.y1 = hi(centre.y + radius);
  return f;
}

bool OccluderSet::reach_can_matter(const QuadFootprint& f, float extent, float push, float near) const {
  float reach = f.z1 + extent * 1.001f;
  float front = f.z0 - push * 1.001f;
  auto touches = [&](const Occluder& o) {
    return o.nearest < reach && o.farthest > front &&
           (f.whole_screen || (o.x0 <= f.x1 && f.x0 <= o.x1 && o.y0 <= f.y1 && f.y0 <= o.y1));
  };
  if (groups_.empty() || !touches(bounds_)) return false;
  // The reach volume: the footprint's rays between the nearest depth a drawn surface can have
  // there and the farthest the soft edges reach. It is convex, so a face slab of a part box
  // with all eight of its corners on one side has the whole volume there.
  glm::vec3 corners[8];
  bool have_corners = false;
  for (const OccluderGroup& g : groups_) {
    if (!touches(g.bound)) continue;
    for (size_t i = g.first; i < g.first + g.count; ++i) {
      if (!touches(occluders_[i])) continue;
      if (f.whole_screen) return true;
      if (!have_corners) {
        const float depths[2] = {std::max(front, near), reach};
        for (int k = 0; k < 8; ++k) {
          const float z = depths[k >> 2];
          corners[k] = glm::vec3(((k & 1) ? f.x1 : f.x0) * z, ((k & 2) ? f.y1 : f.y0) * z, -z);
        }
        have_corners = true;
      }
      if (!separated(boxes_[i], corners)) return true;
    }
  }
  return false;
}

}  // namespace arc
