// Boxes that cover a model's triangles more tightly than its one bounding box: the renderer's
// soft-edge reach test (particle_occluders.h, OccluderSet::soft_can_matter) asks whether an
// opaque surface can lie near a particle, and a fighter's single box is mostly the empty space
// between its wings.
// No GL here, so it is tested on its own.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "assets/model.h"

namespace arc {

struct Box3 {
  glm::vec3 lo, hi;
};

// At most 2^levels axis-aligned boxes in model space such that every triangle of `prims`
// lies wholly inside one of them (each box bounds the whole triangles assigned to it, so
// together they hold every drawn surface point). Triangles are split recursively at the
// median of their centroids along the longest axis of the centroids' bounds; a set of four
// or fewer triangles is not split. Empty when there are no triangles; indices out of range
// are skipped.
std::vector<Box3> cover_boxes(const std::vector<MeshPrimitive>& prims, int levels);

// cover_boxes() of each model the renderer holds, indexed like MeshInstance::model.
using ModelCoverBoxes = std::vector<std::vector<Box3>>;

}  // namespace arc
