// tests/unit/game/human_pilot.h — a test pilot that knows only what the screen shows and plays
// through the player's own input path (no GL).
//
// Each tick it looks at the flight HUD the game would draw at 1280×720 through the World's
// camera (hud_picture(), game/render/hud_layout.h: the crosshair and its beam ring, the target's
// brackets, range cue, missile cue or plasma lead, the off-screen arrow, the radar's dots), and a
// target behind the own hull (game/render/own_cover.h) is not seen. It acts on what it saw a
// reaction time ago (200–300 ms, drawn per seed): its hand moves the mouse in pixels, with a
// wandering aim and moves that are off by a share of their size, and presses keys, all into an
// InputState that LiveInput (game/app/input_bindings.h) turns into InputFrames and commands with
// the default bindings, so the mouse's 0.12°/px, a flick's carry, the quantisation, the set
// throttle and the target keys are the player's own. What it knows of its own hand's recent
// moves stands in for the feel of the mouse (the moves it made since what it sees now).
// Like a player it drops a flare and breaks across a missile's line when the missile warning
// reads near, and orders its wing: F5 (attack my target) as it closes on each new target, F6
// (cover me) when the damage cue shows an attacker out of view and its shield is low.
// It plays the objectives as they read: it flies to the NAV marker a route order puts on the
// HUD while no target is close, cycles its hostile targets (T) until the target panel shows a
// ship an open objective names, and against a ship with subsystems it cycles them (U) to its
// engines or shield generator and launches torpedoes at it in range. On the training range it
// does what the prompt asks: turn, throttle up, afterburner, a flare, an order to the wingman.
//
//   HumanPilot pilot(game.world(), arc::data_root(), /*seed=*/3);
//   InputFrame in;
//   std::vector<Command> keys;
//   pilot.act(game.world(), in, keys);
//   game.step(in, keys);
#pragma once
#include <cstdint>
#include <deque>
#include <string>
#include <vector>
#include <glm/vec2.hpp>

#include "game/app/input_bindings.h"
#include "game/render/hud_rules.h"
#include "game/render/own_cover.h"
#include "game/sim/input.h"

namespace arc {

class World;

struct HumanSkill {
  double reaction_min_s = 0.2, reaction_max_s = 0.3;  // drawn once per seed
  double aim_noise_px = 10.0;       // the hand's wander, standard deviation in pixels at 720 p
  double aim_noise_hold_s = 0.3;    // it picks a new offset this often
  double aim_noise_smooth_s = 0.15; // and drifts to it with this time constant
  double move_error = 0.15;         // each move's size is off by this share (standard deviation)
  double hand_time_s = 0.15;        // a move closes the error it means with this time constant
  double hand_speed = 1.2;          // the fastest hand, in multiples of the ship's full turn rate
  bool fires = true;                // false: never presses a fire button
  bool evades = true;               // breaks across a missile's line when the warning is near
  bool orders = true;               // gives the wing orders (F5 attack my target, F6 cover me)
  int width = 1280, height = 720;   // the window it looks at
};

// What the screen showed on one tick, in window pixels.
struct Sight {
  int64_t tick = 0;
  bool flying = false;          // the flight HUD is up: the own ship is alive
  glm::dvec2 crosshair{0.0};
  bool beam_ring = false;       // "BEAM": the beam fired now would hit
  bool target = false;          // a target is selected: its cues or its arrow are drawn
  bool on_screen = false;       // its brackets are drawn
  bool hidden = false;          // on screen, but the own hull covers it
  glm::dvec2 centre{0.0};       // the brackets' centre
  glm::dvec2 aim{0.0};          // where to put the crosshair: the centre, or the plasma lead
  double bracket = 0;           // the brackets' half-size
  double distance = 0;          // metres, as printed
  bool in_range = false;        // "IN RANGE"
  bool missile_ready = false;   // the missile cue is whole
  bool plasma = false;          // the plasma lead is drawn (aim is the lead)
  glm::dvec2 arrow{0.0};        // off screen: the arrow's direction
  // The radar, in radar radii from its centre (+x right, +y behind), and the height ticks.
  bool hostile_blip = false;
  glm::dvec2 nearest_hostile{0.0};
  double nearest_hostile_rise = 0;
  double target_blip = -1;      // the target dot's distance from the centre; -1 without one
  bool missile_near = false;    // a missile's dot inside the half-range ring
  // The damage cue: the strongest attacker's direction on screen (+y down) and strength, and
  // whether it is in view; the missile warning: the nearest missile's distance (-1: none) and
  // its marker's direction.
  double attack = 0;
  glm::dvec2 attack_dir{0.0};
  bool attacker_in_view = false;
  double missile_m = -1;
  glm::dvec2 missile_dir{0.0};
  double shield = 0, hull = 0;  // the own SHIELD and HULL bars, 0..1
  double energy = 0;            // the own energy bar, 0..1
  double set_throttle = 0;      // the THR bar
  // The nav point of a route order (hud_aim.h NavCue): its diamond or arrow and distance.
  bool nav = false, nav_on_screen = false;
  glm::dvec2 nav_at{0.0}, nav_arrow{0.0};
  double nav_m = 0;
  // The objective rows still open ("[ ] ..."), the target panel's name, and the subsystem cue:
  // whether the target has subsystems to cycle and the part it shows ("" for the whole ship).
  std::vector<std::string> objectives;
  std::string target_name;
  bool target_has_parts = false;
  std::string target_part;
  bool torpedo = false;         // the weapon text reads TORPEDO
  std::string prompt;           // a training step's prompt at the top of the screen ("" for none)
};

class HumanPilot {
 public:
  HumanPilot(const World& w, const std::string& root_dir, uint64_t seed, HumanSkill skill = {});
  // The input for the next tick and the commands of its keys, from the screen as it was.
  void act(const World& w, InputFrame& input, std::vector<Command>& commands);
  // What the screen shows now (the figures count it) and the pilot's reaction time.
  const Sight& now() const { return seen_.back(); }
  double reaction_s() const { return reaction_s_; }

 private:
  Sight look(const World& w) const;
  glm::dvec2 hand_wander(const World& w);
  double move_error(const World& w) const;
  glm::dvec2 track(const World& w, const Sight& seen);
  glm::dvec2 sweep_toward(glm::dvec2 screen_dir) const;
  void choose_keys(const World& w, const Sight& seen);
  void start_break(const World& w, const Sight& seen);
  void order_wing(const World& w, const Sight& seen);
  void fire(const World& w, const Sight& seen);
  bool named(const Sight& seen) const;
  void hunt_named_target(const World& w, const Sight& seen);
  void pick_subsystem(const World& w, const Sight& seen);
  bool follow_nav(const Sight& seen) const;
  void train(const World& w, const Sight& seen, glm::dvec2& move);
  void tap(int code);
  void hold(int code);

  HumanSkill skill_;
  uint64_t seed_;
  std::string root_;
  Bindings bindings_;
  LiveInput input_;
  InputState devices_{};
  HudRules rules_;
  HullBox hull_;
  double reaction_s_ = 0.2;
  size_t delay_ = 12;                 // ticks between a sight and the act on it
  double focal_ = 600;                // window pixels per unit of tan(angle)
  double full_turn_px_ = 12;          // mouse pixels per tick at the ship's full turn rate
  std::deque<Sight> seen_;            // newest last
  std::deque<glm::dvec2> moves_;      // mouse pixels sent on each of the last ticks, newest last
  glm::dvec2 wander_{0.0};
  int64_t last_target_key_ = -1000000, last_missile_ = -1000000, last_flare_ = -1000000;
  int64_t off_screen_since_ = -1;
  int64_t break_until_ = -1, last_break_ = -1000000;  // a break turn lasts until break_until_
  glm::dvec2 break_dir_{1, 0};                         // the screen direction it pulls toward
  uint32_t ordered_target_ = 0;                        // the target an attack order named (index + 1)
  int64_t last_order_ = -1000000;
  std::vector<std::string> hunted_;                    // names the target key showed in this hunt
  int64_t hunt_rest_until_ = -1, last_part_key_ = -1000000, part_rest_until_ = -1;
  int part_presses_ = 0;
};

}  // namespace arc
