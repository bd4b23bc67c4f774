// tests/unit/game/test_pilot.h — a test pilot that plays the way a person does (no GL).
//
// It sees only what the HUD shows (read_hud(): the target's brackets or off-screen arrow, its
// distance, the lead indicator and the crosshair, projected through the World's camera the way
// game/render/hud_layout.cpp projects them at 1280×720), acts on what it saw 200 ms ago, aims
// with a wandering hand, and steers through the player's own input path: quantised InputFrame
// axes and key commands. fly_duel() plays levels/duel.json against the AI; the game tests check
// its win rates with wide bounds, and it flies the bench's recorded dogfight (combat_view). The
// human-like pilot of human_pilot.h sees less: only the cues as drawn, never exact numbers.
//
//   DuelResult r = fly_duel(arc::data_root(), /*difficulty=*/1, /*seed=*/7, PilotKind::Person);
#pragma once
#include <cstdint>
#include <deque>
#include <string>
#include <vector>
#include <glm/vec2.hpp>

#include "game/sim/input.h"
#include "core/data_root.h"

namespace arc {

class Game;
class World;

// The HUD's target picture in pixels (origin top-left), as the player sees it this tick.
struct HudReading {
  int width = 1280, height = 720;
  double focal = 0;               // pixels per unit of tan(angle) at the screen centre
  glm::dvec2 crosshair{0.0};      // where the guns converge, half the beam range ahead
  bool has_target = false;        // a live target is selected (its name and distance are shown)
  bool on_screen = false;         // brackets drawn; otherwise the edge arrow points at it
  glm::dvec2 target{0.0};         // bracket centre
  double bracket = 0;             // bracket half-size
  glm::dvec2 arrow{0.0};          // unit screen direction of the off-screen arrow
  bool has_lead = false;          // lead indicator drawn (the selected secondary is a projectile)
  glm::dvec2 lead{0.0};
  double distance = 0;            // metres, from the target line
  double energy = 0;              // own energy bar, 0..1
  bool plasma = false;            // the weapon line reads "beam + PLASMA" (else missiles)
};

HudReading read_hud(const World& w, int width = 1280, int height = 720);

// How a person flies; the defaults are a fair player with a mouse.
struct PilotSkill {
  double reaction_s = 0.2;           // what it acts on is this old
  double aim_noise_px = 10.0;        // standard deviation of the hand's wander at 720 p
  double aim_noise_hold_s = 0.3;     // the hand picks a new offset this often
  double aim_noise_smooth_s = 0.15;  // and drifts to it with this time constant
  double turn_gain = 3.0;            // stick per radian of aim error
  double turn_damping = 0.3;         // stick per radian per second of the error's change
};

class TestPilot {
 public:
  TestPilot(uint64_t seed, PilotSkill skill = {});
  // The player's input for the next tick and the keys pressed on it, from the HUD of now.
  void act(const World& w, InputFrame& input, std::vector<Command>& commands);

 private:
  glm::dvec2 hand_offset(const World& w);
  void steer(const HudReading& seen, const HudReading& before, const glm::dvec2& hand, double dt, InputFrame& in) const;

  uint64_t seed_;
  PilotSkill skill_;
  std::deque<HudReading> seen_;  // newest last; the front is what it acts on
  glm::dvec2 hand_{0.0};
  int64_t last_target_key_ = -1000000;
};

enum class PilotKind { Person, Idle };

// A level (a path, or one relative to `root_dir`) at a difficulty and seed, as the pilots fly it.
Game load_flight(const std::string& root_dir, const std::string& level, int difficulty, uint64_t seed);
// Flies `g` until its outcome or `max_seconds`: the pilot of `seed` at the controls, or nobody
// (the player's ship drifts) for PilotKind::Idle.
void fly_to_outcome(Game& g, uint64_t seed, PilotKind pilot, double max_seconds);

struct DuelResult {
  bool won = false;
  bool lost = false;
  double seconds = 0;  // when it was decided, or the time limit
};

DuelResult fly_duel(const std::string& root_dir, int difficulty, uint64_t seed, PilotKind pilot,
                    double max_seconds = 240.0);

// Win rate and median time to win over seeds 1..seeds of the duel at one difficulty.
struct DuelRates {
  int fights = 0, wins = 0, losses = 0;
  double win_rate = 0;
  double median_win_s = 0;  // 0 when nothing was won
};
DuelRates duel_rates(const std::string& root_dir, int difficulty, int seeds, PilotKind pilot);

}  // namespace arc
