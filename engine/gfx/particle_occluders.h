// gfx/particle_occluders.h — where opaque meshes stand, as the particle batch sees them (no GL).
//
// Soft edges change a particle's pixels only where an opaque surface lies within its depth
// extent. Each frame the part boxes of every visible mesh instance (cover_boxes.h) become
// Occluders: a view-depth range and a screen rectangle in tangent units, and ViewBoxes: the
// box's three face slabs in view space. soft_can_matter() asks, conservatively, whether any of
// them can reach a particle's quad (QuadBounds): the rectangle and depth range first, then
// whether a face plane has the particle's whole reach volume on its far side. A particle none
// reaches is flagged kSoftClear, skips the depth read and stays bit-identical.
//
// Example, compiled as GfxCpuExamples.SoftCanMatter in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   OccluderSet occluders;
//   occluders.gather(view, model_boxes, to_view, tan_half_x, tan_half_y);
//   bool soft = occluders.soft_can_matter(particle, quad_bounds(particle, to_view, axis_len), near);
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "gfx/cover_boxes.h"
#include "gfx/render_view.h"

namespace arc {

// Set on the uploaded copy of a particle whose soft edges cannot change a pixel: no opaque
// mesh comes within its depth extent anywhere on its quad. shaders/particle.vert reads it.
constexpr uint8_t kSoftClear = 0x80;

// Where a particle's quad can be, as shaders/particle.vert builds it: corners lie within
// `radius` = √(size² + half_long²) of the view-space centre, whatever the billboard (the
// size clamp there only shrinks it), and the density methods' push along the view ray keeps
// the footprint. Computed once per particle for culling and the soft-edge reach test.
struct QuadBounds {
  glm::vec3 centre;  // view space
  float size, half_long, radius;
  bool axis_locked;
};

// `axis_len` is the length of the particle's axis (used only when it is axis-locked).
QuadBounds quad_bounds(const ParticleInstance& p, const glm::mat3& to_view, float axis_len);

// Where a quad lies on screen, in tangent units (x/depth, y/depth), and the view depths it
// spans (a camera-facing quad one depth, an axis-locked one tilted by up to its radius times
// the sine of the view ray's angle to the view axis). A quad that reaches the near plane has an
// unbounded projection: whole_screen, and the rectangle is meaningless. Pushing a quad along the
// view ray (the density methods) keeps its footprint.
struct QuadFootprint {
  float x0, y0, x1, y1;
  float z0, z1;  // nearest and farthest view depth
  bool whole_screen;
};

QuadFootprint quad_footprint(const QuadBounds& q, float near);
// The footprint of a view-space sphere (a cluster's particles together): depths centre ± radius.
QuadFootprint sphere_footprint(const glm::vec3& centre, float radius, float near);

// An opaque mesh as the particle pass sees it: the view depth range of its box and the box's
// screen rectangle in tangent units (x/depth, y/depth); infinite when the box crosses the near
// plane.
struct Occluder {
  float nearest, farthest;
  float x0, y0, x1, y1;
  // Covers nothing: the identity of include().
  static Occluder none();
  void include(const Occluder& o);
};

// A part box in view space as the three slabs between its opposite faces: the set of points p
// with |dot(p, normal[i]) − middle[i]| ≤ half_width[i] for each i (widened a little for the
// GPU's float rounding). A face plane separates a box from a particle's reach where the box's
// screen rectangle and depth range alone cannot: a tilted wall's rectangle and depth range
// cover much of the screen and many depths, its surface only one depth at each pixel.
struct ViewBox {
  glm::vec3 normal[3];  // unit, or zero for a degenerate pair of edges (then never separating)
  float middle[3], half_width[3];
};

// One mesh instance: the union of its part boxes' occluders, and where they are.
struct OccluderGroup {
  Occluder bound;
  size_t first, count;
};

// The occluders of one frame. Buffers are kept between frames.
class OccluderSet {
 public:
  // Every part box of every mesh instance of `view` that is in front of the near plane and on
  // screen (tangent half-extents tan_x, tan_y), under the same camera-relative transform the
  // mesh pass draws with. Instances of unknown models are skipped.
  void gather(const RenderView& view, const ModelCoverBoxes& model_boxes, const glm::mat3& to_view, float tan_x,
              float tan_y);
  // Whether an opaque surface can lie, at some pixel of the particle's quad, within the reach
  // of its soft edges (see the definition for the exact range).
  bool soft_can_matter(const ParticleInstance& p, const QuadBounds& q, float near) const;
  // The same for a footprint whose soft edges reach `extent` behind it and `push` in front.
  bool reach_can_matter(const QuadFootprint& f, float extent, float push, float near) const;
  size_t size() const { return occluders_.size(); }

 private:
  std::vector<Occluder> occluders_;  // one per part box of each visible mesh instance
  std::vector<ViewBox> boxes_;       // the same part boxes, in view space
  std::vector<OccluderGroup> groups_;
  Occluder bounds_ = Occluder::none();  // union of all: most particles of a frame fall outside it
};

}  // namespace arc
