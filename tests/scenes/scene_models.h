// tests/scenes/scene_models.h — models, sprites and particles that test and bench scenes are
// built from, shared so the renderer tests and arcfire-bench draw the same wall and boxes.
//
//   ModelData wall = scenes::wall_model(60, 30, {0.45f, 0.47f, 0.5f, 1}, glm::vec3(0.02f));
//   view.meshes.push_back({renderer.add_model(wall), {0, 0, -6}});
//   view.particles.push_back(scenes::particle({0, 0, -5}, 1.0f, glm::vec3(1, 0.5f, 0.2f), 0.8f, 0.0f));
#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/model.h"
#include "particles/render_output.h"

namespace arc::scenes {

// A w×h rectangle in the XY plane facing +Z, centred at the origin; lit only by `emissive`
// when base is black, which gives tests exactly known background colours.
ModelData wall_model(float w, float h, glm::vec4 base, glm::vec3 emissive);
// An axis-aligned box of half-extents `half` centred at the origin, flat normals per face.
ModelData box_model(glm::vec3 half, glm::vec4 base, glm::vec3 emissive);
Image soft_sprite(int size);  // premultiplied radial falloff

// A camera-facing particle; straight rgb and alpha in, stored premultiplied as
// render_output.h requires.
ParticleInstance particle(glm::vec3 pos, float size, glm::vec3 rgb, float alpha, float burn,
                          SoftEdge soft = SoftEdge::Off);

}  // namespace arc::scenes
