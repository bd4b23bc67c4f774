// gfx/render_view.h — everything the renderer needs for one frame, as plain data.
//
// The game (game/render) fills a RenderView from interpolated simulation state; the renderer
// never sees the game. World positions are double; the renderer subtracts the camera position
// in double before converting to float. Particles arrive already camera-relative, in float.
//
// Example, compiled as RenderViewExample.DescribesAFrame in tests/unit/gfx/test_examples.cpp:
//   RenderView view;
//   view.camera.position = {0.0, 2.0, 30.0};
//   view.camera.fov_y_radians = 1.0;
//   view.meshes.push_back({.model = ship, .position = {0.0, 0.0, 0.0}});  // ship: from Renderer::add_model()
//   ParticleInstance spark{};
//   spark.pos[2] = -30.0f;                   // relative to the camera: 30 units ahead
//   spark.size = 0.5f;
//   spark.color[0] = spark.color[3] = 1.0f;  // rgb premultiplied by alpha, then alpha
//   spark.burn = 1.0f;                       // additive
//   view.particles.push_back(spark);
//   view.hud.texts.push_back({8, 8, 1.0f, {1, 1, 1, 1}, "SHIELD 100"});
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/typed_id.h"
#include "particles/render_output.h"

namespace arc {

struct CameraView {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};  // camera looks along its local −Z, up is +Y
  double fov_y_radians = 1.0;
  double near_plane = 0.5;
  double far_plane = 1.0e7;  // ignored when the infinite far plane is on
};

// A model in a renderer's model table, as Renderer::add_model returned it (null: none).
struct ModelTag;
using ModelId = Id<ModelTag>;

struct MeshInstance {
  ModelId model{};  // instances of a null or unknown model are not drawn
  glm::dvec3 position{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  double scale = 1.0;
  glm::vec3 tint{1.0f};          // multiplies base colour
  float emissive_boost = 1.0f;   // engines glow with throttle
  glm::vec3 flash{0.0f};         // extra light from nearby explosions (rgb, already scaled)
  // The ship's team colour (rgb) and how strongly the model's team regions (materials with
  // Material::team_color, e.g. hull stripes and engine glow) take it (a); a = 0 keeps their own.
  glm::vec4 team_color{0.0f};
};

// 2-D overlay in pixels, origin top-left. Drawn last, unlit, alpha-blended.
struct HudQuad { float x, y, w, h; glm::vec4 color; };
struct HudLine { float x0, y0, x1, y1, width; glm::vec4 color; };
struct HudText { float x, y, scale; glm::vec4 color; std::string text; };
struct HudLayer {
  std::vector<HudQuad> quads;
  std::vector<HudLine> lines;
  std::vector<HudText> texts;
};

struct RenderView {
  CameraView camera;
  // Game time of this frame in seconds (ticks and the interpolation alpha): what the renderer's
  // frame-to-frame smoothing (the overdraw budget) measures time by, so a replayed or headless
  // frame sequence renders the same as the live one. Standing still (0 → 0, a paused game)
  // keeps the smoothing where it is; a jump back or of more than half a second restarts it.
  double time_seconds = 0.0;
  glm::vec3 light_direction{-0.4f, -0.6f, -0.7f};  // direction light travels, world space
  glm::vec3 light_color{1.0f, 0.96f, 0.9f};
  glm::vec3 ambient{0.08f, 0.09f, 0.12f};
  uint64_t starfield_seed = 1;
  std::vector<MeshInstance> meshes;
  // Camera-relative particles already culled by cluster; the renderer sorts and draws them.
  std::vector<ParticleInstance> particles;
  HudLayer hud;
};

}  // namespace arc
