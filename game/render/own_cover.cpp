// Whether a point is behind the own ship's silhouette: the convex hull of its bounding box's
// corners projected from the eye.
#include "game/render/own_cover.h"

#include <algorithm>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "game/sim/world.h"

namespace arc {
namespace {

double cross2(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// The convex hull of points, counter-clockwise (monotone chain).
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> p) {
  std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<glm::dvec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace

bool covered_by_hull(const glm::dvec3& eye, const glm::dquat& eye_orientation, const Ship& me, const HullBox& box,
                     const glm::dvec3& point) {
  const glm::dquat inv = glm::conjugate(eye_orientation);
  const glm::dvec3 t = inv * (point - eye), c = inv * (me.position - eye);
  if (t.z >= -1e-6 || glm::dot(t, t) <= glm::dot(c, c)) return false;  // behind the eye, or nearer than the ship
  std::vector<glm::dvec2> corners;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 local(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
    const glm::dvec3 v = inv * (me.position + me.orientation * local - eye);
    if (v.z >= -1e-6) return true;  // the eye inside the hull's box
    corners.push_back({v.x / -v.z, v.y / -v.z});
  }
  const std::vector<glm::dvec2> h = convex_hull(corners);
  const glm::dvec2 p(t.x / -t.z, t.y / -t.z);
  for (size_t i = 0; i < h.size(); ++i)
    if (cross2(h[i], h[(i + 1) % h.size()], p) < 0) return false;
  return true;
}

}  // namespace arc
