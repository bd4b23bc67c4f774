// The effect workbench's stage and orbit camera (game/workbench), without a window: the
// timeline's loop, speed and tick steps, a step back and forth landing on the same state as
// playing, and a camera that frames what it is asked to and never looks straight up.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "game/workbench/effect_document.h"
#include "game/workbench/orbit_camera.h"
#include "game/workbench/workbench_stage.h"
#include "core/data_root.h"

namespace arc {
namespace {

std::unique_ptr<EffectDocument> open_effect(const char* name) {
  std::string error;
  auto doc = EffectDocument::open(arc::data_root() + "/assets/effects/" + name + ".json", error);
  EXPECT_TRUE(doc) << error;
  return doc;
}

TEST(WorkbenchStage, StepsBackAndForthToThePlayedState) {
  auto doc = open_effect("ship_explosion");
  WorkbenchStage stage;
  stage.set_effect(doc->library(), doc->name());
  stage.set_loop_seconds(2.0);
  for (int i = 0; i < 30; ++i) stage.advance(1.0 / 60.0);
  ASSERT_EQ(stage.tick(), 30u);
  const uint64_t played = stage.state_hash();
  const uint32_t live = stage.counts().live_particles;
  EXPECT_GT(live, 0u);
  stage.step_by(-1);
  EXPECT_EQ(stage.tick(), 29u);
  EXPECT_FALSE(stage.playing());  // a step pauses
  EXPECT_NE(stage.state_hash(), played);
  stage.step_by(1);
  EXPECT_EQ(stage.tick(), 30u);
  EXPECT_EQ(stage.state_hash(), played);
  stage.scrub(5);
  stage.scrub(30);
  EXPECT_EQ(stage.state_hash(), played);
  EXPECT_EQ(stage.counts().live_particles, live);
}

TEST(WorkbenchStage, LoopsAtItsPeriodAndClampsSpeed) {
  auto doc = open_effect("hull_sparks");
  WorkbenchStage stage;
  stage.set_effect(doc->library(), doc->name());
  stage.set_loop_seconds(0.5);  // 30 ticks
  EXPECT_EQ(stage.loop_ticks(), 30u);
  stage.set_speed(10.0);
  EXPECT_EQ(stage.speed(), 4.0);
  stage.set_speed(0.01);
  EXPECT_EQ(stage.speed(), 0.1);
  stage.set_speed(1.0);
  for (int i = 0; i < 40; ++i) stage.advance(1.0 / 60.0);
  EXPECT_EQ(stage.tick(), 9u);  // 0..30 is 31 ticks: tick 40 of play is tick 9 of the second loop
  stage.step_by(-10);           // back past tick 0 wraps to the loop's end
  EXPECT_EQ(stage.tick(), 30u);
}

TEST(WorkbenchStage, CirclingBackdropMovesTheFocusWithTheShip) {
  auto doc = open_effect("engine_exhaust");
  WorkbenchStage stage;
  stage.set_effect(doc->library(), doc->name());
  stage.set_models({StageModel{"viper", ModelId{1u}, {-5, -2, -8}, {5, 2, 8}, 9.0}}, StageModel{});
  stage.set_backdrop({BackdropKind::Circling, 0, true});
  stage.scrub(0);
  const glm::dvec3 start = stage.focus();
  stage.scrub(60);
  EXPECT_GT(glm::length(stage.focus() - start), 10.0);
  RenderView view;
  stage.build_view(OrbitCamera{}.view(), 640, 360, view);
  ASSERT_EQ(view.meshes.size(), 1u);
  // At the stern: the ship is drawn 8 m ahead of the effect's owner, along its nose (−Z).
  EXPECT_NEAR(glm::length(view.meshes[0].position - stage.focus()), 8.0, 1e-9);
  EXPECT_GT(stage.counts().live_particles, 0u);
}

TEST(OrbitCamera, FramesASphereAndLooksAtIt) {
  OrbitCamera cam;
  cam.drag(120.0, -40.0);
  cam.frame({3.0, -2.0, 7.0}, 12.0);
  const CameraView v = cam.view();
  const glm::dvec3 to_target = glm::dvec3(3.0, -2.0, 7.0) - v.position;
  const double d = glm::length(to_target);
  EXPECT_LE(std::asin(12.0 / d), v.fov_y_radians * 0.5);      // the sphere fits the view's height
  EXPECT_GT(std::asin(12.0 / d), v.fov_y_radians * 0.5 * 0.8);  // and fills most of it
  const glm::dvec3 forward = v.orientation * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(glm::dot(forward, to_target / d), 1.0, 1e-9);
  cam.zoom(1.0);
  EXPECT_NEAR(cam.distance, d * 0.8, 1e-9);
}

TEST(OrbitCamera, PitchStopsShortOfThePoles) {
  OrbitCamera cam;
  cam.drag(0.0, -1e6);
  const glm::dvec3 forward = cam.view().orientation * glm::dvec3(0, 0, -1);
  EXPECT_LT(std::abs(forward.y), 0.9999);
  EXPECT_GT(forward.y, 0.99);  // looking up, nearly straight
}

}  // namespace
}  // namespace arc
