// The chase view's lift over the own hull (game/render/chase_framing.h): a hostile the rig's
// view would see only through the own hull shows above it in the frame's camera, the hull
// staying below the crosshair and on screen; the lift grows and falls away smoothly as the
// hostile crosses the silhouette, and the view stays put when nothing is behind the hull.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "assets/model.h"
#include "game/render/chase_framing.h"
#include "game/render/own_cover.h"
#include "game/render/render_view_builder.h"
#include "game/render/screen_projection.h"
#include "game/sim/world.h"
#include "test_helpers.h"

namespace arc {
namespace {

struct Duel {
  Game game = Game::load_level(test::repo("levels/duel.json"), test::options());
  HullBox box;
  Duel() {
    game.step(InputFrame{});
    const ModelData m = load_model(test::repo("assets/models/viper.glb"));
    box = {glm::dvec3(m.bounds_min), glm::dvec3(m.bounds_max)};
  }
  World& w() { return const_cast<World&>(game.world()); }
  Ship& me() { return w().ship(w().player); }
  Ship& enemy() {
    for (Ship& s : w().ships)
      if (s.alive && w().hostile(me(), s)) return s;
    throw std::runtime_error("the duel has no enemy");
  }
  // The enemy `beyond` metres past the point `local` of the own ship (its frame), on the rig's line of sight.
  void place_behind(const glm::dvec3& local, double beyond) {
    const glm::dvec3 eye = w().camera.position, at = me().position + me().orientation * local;
    const glm::dvec3 p = eye + glm::normalize(at - eye) * (glm::length(at - eye) + beyond);
    enemy().position = enemy().prev_position = p;
  }
  double rise() {
    const CameraView cam = frame_camera(w(), 1.0, CameraSettings{});
    return glm::dot(cam.position - w().camera.position, w().camera.orientation * glm::dvec3(0, 1, 0));
  }
};

TEST(ChaseFraming, HostileBehindTheNoseShowsAboveTheHull) {
  Duel d;
  for (const glm::dvec3 local : {glm::dvec3(0, 1.5, -5), glm::dvec3(2.5, 1.0, -2), glm::dvec3(-1.0, 0.5, 0)}) {
    for (double beyond : {60.0, 200.0, 600.0}) {
      d.place_behind(local, beyond);
      const glm::dvec3 target = d.enemy().position;
      // The rig's own view looks at it through the hull...
      ASSERT_TRUE(covered_by_hull(d.w().camera.position, d.w().camera.orientation, d.me(), d.box, target))
          << local.x << " " << local.y << " " << local.z << " beyond " << beyond;
      // ... the frame's camera over it.
      const CameraView cam = frame_camera(d.w(), 1.0, CameraSettings{});
      EXPECT_FALSE(covered_by_hull(cam.position, cam.orientation, d.me(), d.box, target))
          << local.x << " " << local.y << " " << local.z << " beyond " << beyond << " rise " << d.rise();
      // The hull stays on screen, below the crosshair's line.
      const Projector pr = Projector::of(cam, 1280, 720);
      glm::dvec2 cross, px;
      ASSERT_TRUE(pr.project(crosshair_point(d.w(), d.me(), 1.0), cross));
      for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? d.box.hi.x : d.box.lo.x, i & 2 ? d.box.hi.y : d.box.lo.y,
                                i & 4 ? d.box.hi.z : d.box.lo.z);
        ASSERT_TRUE(pr.project(d.me().position + d.me().orientation * corner, px));
        EXPECT_GT(px.y, cross.y + 20.0);
        EXPECT_LT(px.y, 720.0);
      }
    }
  }
}

// The crosshair tells where the nose points at the target's range: with the target on the nose
// line near or far, or behind the hull with the view lifted over it, the crosshair stands on the
// nose line at the target's range (within a pixel at 720p). A crosshair at half the beam's range
// ahead for every target lies over 5 px off one 600 m down the nose line (metres there: a miss),
// the eye being above that line.
TEST(ChaseFraming, TheCrosshairOnTheTargetMeansTheNoseOnIt) {
  Duel d;
  d.game.step(InputFrame{}, {Command::TargetNearest});
  ASSERT_TRUE(d.me().target);
  const glm::dvec3 nose = forward_of(d.me().orientation);
  auto check = [&](const char* what) {
    const CameraView cam = frame_camera(d.w(), 1.0, CameraSettings{});
    const Projector pr = Projector::of(cam, 1280, 720);
    const double ahead = glm::dot(d.enemy().position - d.me().position, nose);
    glm::dvec2 cross, on_nose, fixed;
    ASSERT_TRUE(pr.project(crosshair_point(d.w(), d.me(), 1.0), cross));
    ASSERT_TRUE(pr.project(d.me().position + nose * ahead, on_nose));
    ASSERT_TRUE(pr.project(crosshair_point(d.me(), 1.0), fixed));
    EXPECT_LT(glm::length(cross - on_nose), 1.0) << what << " " << ahead << " m ahead, rise " << d.rise();
    if (ahead > 550.0) {
      EXPECT_GT(glm::length(fixed - on_nose), 5.0) << what << " " << ahead << " m ahead";
    }
  };
  for (double range : {120.0, 325.0, 500.0, 640.0}) {
    d.enemy().position = d.enemy().prev_position = d.me().position + nose * range;
    check("on the nose line");
  }
  for (double beyond : {100.0, 300.0, 600.0}) {
    d.place_behind(glm::dvec3(0, 1.5, -5), beyond);
    ASSERT_GT(d.rise(), 0.5);
    check("behind the hull");
  }
}

TEST(ChaseFraming, NothingBehindTheHullLeavesTheRigsView) {
  Duel d;
  const Ship& me = d.me();
  d.enemy().position = d.enemy().prev_position = me.position + forward_of(me.orientation) * 600.0;
  EXPECT_EQ(d.rise(), 0.0);
  // Far below the nose: the lift is for what lies ahead.
  d.enemy().position = d.enemy().prev_position = me.position + me.orientation * glm::dvec3(0, -400, -300);
  EXPECT_EQ(d.rise(), 0.0);
}

// A hostile sweeping through the silhouette, across and up, in steps of 0.1°: the lift changes
// by at most 0.6 m a step (a snap would move it metres) and is back to nothing on the far side.
TEST(ChaseFraming, LiftChangesSmoothlyAcrossTheSilhouette) {
  Duel d;
  const glm::dvec3 eye = d.w().camera.position;
  const glm::dquat view = d.w().camera.orientation;
  const glm::dvec3 through = d.me().position + d.me().orientation * glm::dvec3(0, 1.0, -3);
  const glm::dvec3 centre = glm::normalize(through - eye);
  const glm::dvec3 right = view * glm::dvec3(1, 0, 0), up = view * glm::dvec3(0, 1, 0);
  for (const glm::dvec3 axis : {right, up}) {
    double prev = -1, most = 0, jump = 0;
    for (int i = -250; i <= 250; ++i) {
      const glm::dvec3 dir = glm::normalize(centre + axis * std::tan(i * 0.1 * 3.14159265358979 / 180.0));
      d.enemy().position = d.enemy().prev_position = eye + dir * 250.0;
      const double r = d.rise();
      if (prev >= 0) jump = std::max(jump, std::fabs(r - prev));
      most = std::max(most, r);
      prev = r;
    }
    EXPECT_GT(most, 3.0);
    EXPECT_LT(jump, 0.6);
    EXPECT_EQ(prev, 0.0);
  }
}

}  // namespace
}  // namespace arc
