// gfx/cover_boxes.cpp — median splits of a model's triangles into tight boxes (no GL).
#include "gfx/cover_boxes.h"

#include <algorithm>
#include <array>

namespace arc {
namespace {

using Triangle = std::array<glm::vec3, 3>;

glm::vec3 centroid(const Triangle& t) { return (t[0] + t[1] + t[2]) / 3.0f; }

void split(std::vector<Triangle>& tris, size_t begin, size_t end, int levels, std::vector<Box3>& out) {
  if (levels <= 0 || end - begin <= 4) {
    Box3 b{tris[begin][0], tris[begin][0]};
    for (size_t i = begin; i < end; ++i)
      for (const glm::vec3& p : tris[i]) b.lo = glm::min(b.lo, p), b.hi = glm::max(b.hi, p);
    out.push_back(b);
    return;
  }
  glm::vec3 lo = centroid(tris[begin]), hi = lo;
  for (size_t i = begin; i < end; ++i) {
    const glm::vec3 c = centroid(tris[i]);
    lo = glm::min(lo, c), hi = glm::max(hi, c);
  }
  const glm::vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const size_t mid = begin + (end - begin) / 2;
  std::nth_element(tris.begin() + std::ptrdiff_t(begin), tris.begin() + std::ptrdiff_t(mid), tris.begin() + std::ptrdiff_t(end),
                   [axis](const Triangle& a, const Triangle& b) { return centroid(a)[axis] < centroid(b)[axis]; });
  split(tris, begin, mid, levels - 1, out);
  split(tris, mid, end, levels - 1, out);
}

}  // namespace

std::vector<Box3> cover_boxes(const std::vector<MeshPrimitive>& prims, int levels) {
  std::vector<Triangle> tris;
  for (const MeshPrimitive& p : prims)
    for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
      const uint32_t a = p.indices[i], b = p.indices[i + 1], c = p.indices[i + 2];
      if (a >= p.positions.size() || b >= p.positions.size() || c >= p.positions.size()) continue;
      tris.push_back({p.positions[a], p.positions[b], p.positions[c]});
    }
  std::vector<Box3> out;
  if (!tris.empty()) split(tris, 0, tris.size(), levels, out);
  return out;
}

}  // namespace arc
