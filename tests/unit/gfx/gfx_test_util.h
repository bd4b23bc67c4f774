// Shared scene pieces for the renderer tests: one EGL context per process, a wall and box
// model, a soft round sprite, and particle construction with premultiplied colour.
#pragma once
#include <memory>
#include <string>

#include "assets/model.h"
#include "gfx/renderer.h"
#include "platform/platform.h"

namespace arc::test {

// The process-wide headless context, or nullptr with the reason in `why`.
HeadlessContext* headless(std::string& why);

// A w×h rectangle in the XY plane facing +Z, centred at the origin; lit only by `emissive`
// when base is black, which gives tests exactly known background colours.
ModelData wall_model(float w, float h, glm::vec4 base, glm::vec3 emissive);
ModelData box_model(glm::vec3 half, glm::vec4 base, glm::vec3 emissive);
Image soft_sprite(int size);  // premultiplied radial falloff

// Straight rgb and alpha in; stored premultiplied as render_output.h requires.
ParticleInstance particle(glm::vec3 pos, float size, glm::vec3 rgb, float alpha, float burn,
                          SoftEdge soft = SoftEdge::Off);

RenderSettings plain_settings();  // no near fade, full sort, given depth mode defaults
void dump_if_asked(const std::string& name, const Image& img);  // $ARCFIRE_GFX_DUMP/<name>.png
float channel(const Image& img, int x, int y, int c);  // 0..1

}  // namespace arc::test
