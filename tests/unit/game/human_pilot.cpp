// tests/unit/game/human_pilot.cpp — the screen-reading test pilot: what it sees (the HUD as
// drawn), when (a reaction time late), and its hand on the mouse and the keys through LiveInput.
#include "human_pilot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <glm/geometric.hpp>

#include "assets/model.h"
#include "core/data_layers.h"
#include "core/rng.h"
#include "game/render/camera_settings.h"
#include "game/render/hud_layout.h"
#include "game/render/hud_objectives.h"
#include "game/render/hud_training.h"
#include "game/render/render_view_builder.h"
#include "game/sim/capital.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr uint64_t kReactionStream = 0x5245414354ull;  // "REACT"
constexpr uint64_t kWanderStream = 0x57414e444552ull;  // "WANDER"
constexpr uint64_t kMoveStream = 0x4d4f5645ull;        // "MOVE"
constexpr double kRadToDeg = 57.29577951308232;

// A standard normal value from two uniforms (Box–Muller).
double gaussian(const Rng& rng, uint64_t index) {
  const double r = std::sqrt(-2.0 * std::log(1.0 - rng.uniform(index * 2)));
  return r * std::cos(6.283185307179586 * rng.uniform(index * 2 + 1));
}

glm::dvec2 unit_or(glm::dvec2 v, glm::dvec2 fallback) {
  const double l = glm::length(v);
  return l > 1e-9 ? v / l : fallback;
}

// Where to turn for a dot on the radar (+y behind): toward its side and height when ahead;
// when behind, round toward its side.
glm::dvec2 radar_direction(const Sight& s) {
  const glm::dvec2 rel = s.nearest_hostile;
  if (rel.y < 0) return unit_or({rel.x, -s.nearest_hostile_rise}, {1, 0});
  return unit_or({rel.x >= 0 ? 1.0 : -1.0, -0.5 * s.nearest_hostile_rise}, {1, 0});
}

}  // namespace

HumanPilot::HumanPilot(const World& w, const std::string& root_dir, uint64_t seed, HumanSkill skill)
    : skill_(skill),
      seed_(seed),
      root_(root_dir),
      bindings_(load_bindings(data_file(root_dir, "assets/settings/bindings.json"))),
      input_(bindings_) {
  if (!w.player) throw std::invalid_argument(w.level.path + ": the test pilot needs a level with a player ship");
  rules_ = load_hud_rules(data_file(root_dir, "assets/settings/hud.json"));
  const Rng rng{seed_, kReactionStream, 0};
  reaction_s_ = rng.range(0, skill_.reaction_min_s, skill_.reaction_max_s);
  delay_ = size_t(std::max<int64_t>(1, seconds_to_ticks(w, reaction_s_)));
  const Ship& me = w.ship(w.player);
  // As the window loop sets it up for the flown ship.
  input_.set_flight_scale({me.cls->turn_rate[0], me.cls->turn_rate[1], w.dt});
  input_.set_screen_height(skill_.height);
  input_.reset_throttle();
  input_.sample(devices_);  // the capture jump of the first sample is ignored
  const ModelData model = load_model(data_file(root_dir, w.model_paths[me.model.index()]));
  hull_ = {glm::dvec3(model.bounds_min), glm::dvec3(model.bounds_max)};
  focal_ = (skill_.height * 0.5) / std::tan(w.level.camera.fov_deg / kRadToDeg * 0.5);
  full_turn_px_ = std::min(me.cls->turn_rate[0], me.cls->turn_rate[1]) * w.dt / bindings_.mouse_sensitivity;
  // Before its first look has reached the hand, the hand does nothing.
  seen_.assign(delay_, Sight{});
  seen_.push_back(look(w));
}

// One field of the Sight per cue the HUD draws.
Sight HumanPilot::look(const World& w) const {
  Sight s;
  s.tick = w.tick;
  const CameraView cam = frame_camera(w, 1.0, CameraSettings{});
  HudState hud;
  hud.rules = rules_;
  const HudPicture pic = hud_picture(w, cam, hud, 1.0, skill_.width, skill_.height);
  s.flying = pic.flying && w.focus_ship() == w.player;
  if (!s.flying) return s;
  const Ship& me = w.ship(w.player);
  s.energy = me.cls->energy > 0 ? me.energy / me.cls->energy : 0.0;
  s.shield = me.cls->shield > 0 ? me.shield / me.cls->shield : 0.0;
  s.hull = me.hull / me.cls->hull;
  for (const ThreatCue& a : pic.threats.attackers) {
    if (a.strength <= s.attack) continue;
    s.attack = a.strength;
    s.attack_dir = a.dir;
    s.attacker_in_view = a.in_view;
  }
  s.missile_m = pic.threats.missile_m;
  if (!pic.threats.missiles.empty()) s.missile_dir = pic.threats.missiles.front();
  s.set_throttle = input_.set_throttle();
  s.crosshair = pic.aim.crosshair;
  s.beam_ring = pic.aim.beam_ring_lit;
  const TargetCues& t = pic.aim.target;
  s.target = t.selected;
  s.on_screen = t.on_screen;
  s.distance = t.distance;
  s.bracket = t.half_size;
  s.in_range = t.in_range;
  s.missile_ready = t.missile_cue && t.missile_ready && t.lock >= 1.0;  // clicks on "LOCK"
  s.plasma = t.plasma_lead;
  s.centre = t.centre;
  s.aim = t.plasma_lead ? t.lead : t.centre;
  s.arrow = t.arrow_dir;
  const NavCue& nav = pic.aim.nav;
  s.nav = nav.shown, s.nav_on_screen = nav.on_screen, s.nav_at = nav.at, s.nav_arrow = nav.arrow_dir;
  s.nav_m = nav.distance;
  if (w.mission)
    for (size_t i = 0; i < w.mission->objectives.size(); ++i)
      if (w.mission->objectives[i].revealed && w.mission->objectives[i].status == ObjectiveStatus::Pending)
        s.objectives.push_back(objective_row(w, i));
  s.torpedo = me.secondary == SecondaryWeapon::Torpedo && me.cls->torpedo.present;
  if (training_prompt_shown(w)) s.prompt = w.level.training.steps[size_t(w.training->step)].prompt;
  if (t.selected) {
    const Ship& ts = w.ship(me.target);
    s.target_name = ts.name;
    s.target_has_parts = !ts.parts.empty();
    const int part = target_part(w, me);
    s.target_part = part >= 0 ? part_name(*ts.cls, size_t(part)) : "";
  }
  if (t.on_screen && w.camera_mode != CameraMode::Cockpit)
    s.hidden = covered_by_hull(cam.position, cam.orientation, me, hull_, w.ship(me.target).position);
  const glm::dvec2 centre(pic.radar.x + pic.radar.w * 0.5, pic.radar.y + pic.radar.h * 0.5);
  const double half = std::max(pic.radar.w * 0.5, 1e-9);
  double nearest = 1e30;
  for (const RadarBlip& b : pic.radar_blips) {
    const glm::dvec2 rel = (b.at - centre) / half;
    const double r = glm::length(rel);
    if (b.target) s.target_blip = r;
    if (b.kind == RadarBlipKind::Missile && r < 0.5) s.missile_near = true;
    if (b.kind != RadarBlipKind::Hostile || r >= nearest) continue;
    nearest = r;
    s.hostile_blip = true;
    s.nearest_hostile = rel;
    s.nearest_hostile_rise = b.rise / half;
  }
  return s;
}

// The hand wanders: every hold period it drifts toward a fresh Gaussian offset.
glm::dvec2 HumanPilot::hand_wander(const World& w) {
  const int64_t hold = std::max<int64_t>(1, seconds_to_ticks(w, skill_.aim_noise_hold_s));
  const Rng rng{seed_, kWanderStream, static_cast<uint64_t>(w.tick / hold)};
  const glm::dvec2 goal = glm::dvec2(gaussian(rng, 0), gaussian(rng, 1)) * skill_.aim_noise_px;
  wander_ += (goal - wander_) * (1.0 - std::exp(-w.dt / skill_.aim_noise_smooth_s));
  return wander_ * (skill_.height / 720.0);
}

// How far off the hand's moves are: a new factor every hold period.
double HumanPilot::move_error(const World& w) const {
  const int64_t hold = std::max<int64_t>(1, seconds_to_ticks(w, skill_.aim_noise_hold_s));
  const Rng rng{seed_, kMoveStream, static_cast<uint64_t>(w.tick / hold)};
  return std::max(0.2, 1.0 + skill_.move_error * gaussian(rng, 0));
}

// The mouse move that brings the crosshair onto what it aims at: the error it saw, in mouse
// pixels (the bindings' degrees per pixel), less the moves it made since, closed over the hand's
// time, no faster than the hand goes.
glm::dvec2 HumanPilot::track(const World& w, const Sight& seen) {
  const glm::dvec2 err = seen.aim + hand_wander(w) - seen.crosshair;
  glm::dvec2 m(std::atan(err.x / focal_), std::atan(err.y / focal_));
  m *= kRadToDeg / bindings_.mouse_sensitivity;
  const size_t since = std::min(delay_, moves_.size());
  for (size_t i = moves_.size() - since; i < moves_.size(); ++i) m -= moves_[i];
  glm::dvec2 move = m * (w.dt / skill_.hand_time_s) * move_error(w);
  const double fastest = skill_.hand_speed * full_turn_px_, len = glm::length(move);
  if (len > fastest) move *= fastest / len;
  return move;
}

// Off screen: the hand sweeps toward the arrow (or a radar dot) as fast as the ship turns.
glm::dvec2 HumanPilot::sweep_toward(glm::dvec2 screen_dir) const {
  return unit_or(screen_dir, {1, 0}) * full_turn_px_;
}

void HumanPilot::hold(int code) {
  if (code < 0) return;
  if (code >= kMouseButtonBase) {
    const size_t b = size_t(code - kMouseButtonBase);
    if (b < devices_.mouse_buttons.size()) devices_.mouse_buttons[b] = true;
  } else if (size_t(code) < devices_.keys.size()) {
    devices_.keys[size_t(code)] = true;
  }
}

// Down for one frame: LiveInput sees the press; the next frame lets it go.
void HumanPilot::tap(int code) { hold(code); }

// The target keys, the throttle, the afterburner and the countermeasure key.
void HumanPilot::choose_keys(const World& w, const Sight& seen) {
  const Bindings& b = bindings_;
  if (!seen.target) {
    // R (nearest hostile), pressed again if nothing happened half a second later.
    if (w.tick - last_target_key_ >= seconds_to_ticks(w, 0.5)) tap(b.target_nearest), last_target_key_ = w.tick;
    off_screen_since_ = -1;
  } else if (!seen.on_screen) {
    if (off_screen_since_ < 0) off_screen_since_ = w.tick;
    // Long off screen while the radar shows a hostile much nearer than the target: R for it.
    const bool nearer = seen.hostile_blip && seen.target_blip > 0 &&
                        glm::length(seen.nearest_hostile) < 0.6 * seen.target_blip;
    if (nearer && !named(seen) && w.tick - off_screen_since_ > seconds_to_ticks(w, 3.0) &&
        w.tick - last_target_key_ > seconds_to_ticks(w, 3.0))
      tap(b.target_nearest), last_target_key_ = w.tick;
  } else {
    off_screen_since_ = -1;
  }
  const double d = seen.distance;
  const bool nav = follow_nav(seen);
  const bool training_speed = seen.prompt.find("Throttle up") != std::string::npos ||
                              seen.prompt.find("Afterburner") != std::string::npos;
  const double wanted = training_speed ? 1.0 : nav ? 1.0 : !seen.target ? 0.5 : d > 800 ? 1.0 : d > 400 ? 0.8 : d > 150 ? 0.55 : 0.35;
  // The THR bar moves while the key is down; the hand lets go at the mark.
  const double set = input_.set_throttle();
  if (set < wanted - 0.03) hold(b.throttle.positive);
  if (set > wanted + 0.03) hold(b.throttle.negative);
  if (seen.target && seen.on_screen && d > 1500 && seen.energy > 0.5) hold(b.afterburner);
  if (nav && seen.nav_on_screen && seen.nav_m > 1200 && seen.energy > 0.5) hold(b.afterburner);
  const bool missile_close = seen.missile_near || (seen.missile_m >= 0 && seen.missile_m < 500);
  if (missile_close && w.tick - last_flare_ >= seconds_to_ticks(w, 1.5))
    tap(b.countermeasure), last_flare_ = w.tick;
}

// A break turn when the missile warning reads under 600 m: hard across the missile's line (its
// marker's direction turned a quarter) for a second on the afterburner, so it overshoots.
void HumanPilot::start_break(const World& w, const Sight& seen) {
  if (!skill_.evades || w.tick < break_until_ || w.tick - last_break_ < seconds_to_ticks(w, 3.0)) return;
  if (seen.missile_m < 0 || seen.missile_m >= 600) return;
  break_dir_ = unit_or({-seen.missile_dir.y, seen.missile_dir.x}, {1, 0});
  last_break_ = w.tick;
  break_until_ = w.tick + seconds_to_ticks(w, 1.0);
}

// F5 (attack my target) once the pilot closes on a new target; F6 (cover me) while hunted.
void HumanPilot::order_wing(const World& w, const Sight& seen) {
  if (!skill_.orders || w.tick - last_order_ < seconds_to_ticks(w, 2.0)) return;
  const Ship& me = w.ship(w.player);  // the target panel names the target
  const uint32_t target = me.target ? uint32_t(me.target.index()) + 1 : 0;
  const bool hunted = seen.attack > 0.5 && !seen.attacker_in_view && seen.shield < 0.4;
  if (hunted && w.tick - last_order_ > seconds_to_ticks(w, 8.0)) {
    tap(bindings_.order_cover), last_order_ = w.tick, ordered_target_ = 0;
  } else if (target && target != ordered_target_ && seen.on_screen && seen.distance < 1500) {
    tap(bindings_.order_attack), last_order_ = w.tick, ordered_target_ = target;
  }
}

// An open objective names the target the panel shows; while a primary row is open, a bonus
// row's target waits, as a player reads the list.
bool HumanPilot::named(const Sight& seen) const {
  if (seen.target_name.empty()) return false;
  const auto bonus = [](const std::string& row) { return row.find("(bonus)") != std::string::npos; };
  const bool primary_open = std::any_of(seen.objectives.begin(), seen.objectives.end(),
                                        [&](const std::string& row) { return !bonus(row); });
  for (const std::string& row : seen.objectives)
    if (!(primary_open && bonus(row)) && row.find(seen.target_name) != std::string::npos) return true;
  return false;
}

// Open objectives but a target they do not name: T (next hostile) every 0.4 s, remembering the
// names it shows; once a name comes round again none is named, and it rests 10 s.
void HumanPilot::hunt_named_target(const World& w, const Sight& seen) {
  // Without torpedoes a capital ship no open objective names is left to the big guns: T on.
  if (seen.target && seen.target_has_parts && !seen.torpedo && !named(seen)) {
    if (w.tick - last_target_key_ >= seconds_to_ticks(w, 0.4)) tap(bindings_.target_next_hostile), last_target_key_ = w.tick;
    return;
  }
  if (!seen.target || seen.objectives.empty() || named(seen)) {
    hunted_.clear();
    return;
  }
  if (w.tick < hunt_rest_until_ || w.tick - last_target_key_ < seconds_to_ticks(w, 0.4)) return;
  if (std::find(hunted_.begin(), hunted_.end(), seen.target_name) != hunted_.end()) {
    hunted_.clear();
    hunt_rest_until_ = w.tick + seconds_to_ticks(w, 10.0);
    return;
  }
  hunted_.push_back(seen.target_name);
  tap(bindings_.target_next_hostile), last_target_key_ = w.tick;
}

// A target with subsystems: U until the cue shows its shield generator or engines (the
// briefing's advice); after a whole round without them it rests 10 s.
void HumanPilot::pick_subsystem(const World& w, const Sight& seen) {
  if (!seen.target || !seen.target_has_parts) return;
  if (seen.target_part == "shield generator" || seen.target_part == "engines") {
    part_presses_ = 0;
    return;
  }
  if (w.tick < part_rest_until_ || w.tick - last_part_key_ < seconds_to_ticks(w, 0.3)) return;
  if (++part_presses_ > 8) {
    part_presses_ = 0;
    part_rest_until_ = w.tick + seconds_to_ticks(w, 10.0);
    return;
  }
  tap(bindings_.target_subsystem), last_part_key_ = w.tick;
}

// What a training prompt asks for, read off its words: a turn, the throttle or the afterburner
// held, a flare, an order to the wingman; the rest (target, beam, missile) is flying as usual.
void HumanPilot::train(const World& w, const Sight& seen, glm::dvec2& move) {
  const std::string& p = seen.prompt;
  if (p.find("Turn the ship") != std::string::npos) move = sweep_toward({1, 0});
  const bool burner = p.find("Afterburner") != std::string::npos;
  if (burner || p.find("Throttle up") != std::string::npos) {
    if (input_.set_throttle() < 0.97) hold(bindings_.throttle.positive);
    if (burner && seen.energy > 0.2) hold(bindings_.afterburner);
  }
  if (p.find("drop a flare") != std::string::npos && w.tick - last_flare_ >= seconds_to_ticks(w, 1.0))
    tap(bindings_.countermeasure), last_flare_ = w.tick;
  if (p.find("wingman has joined") != std::string::npos && w.tick - last_order_ >= seconds_to_ticks(w, 1.0))
    tap(bindings_.order_attack), last_order_ = w.tick;
}

// The NAV marker leads while no target is close.
bool HumanPilot::follow_nav(const Sight& seen) const {
  return seen.nav && (!seen.target || seen.distance > 1500);
}

// The beam while the crosshair is on the target in range (or the beam ring lit); a missile
// click once the cue reads LOCK; plasma while the lead sits on the crosshair.
void HumanPilot::fire(const World& w, const Sight& seen) {
  if (!skill_.fires || !seen.target || !seen.on_screen || seen.hidden) return;
  const double off = glm::length(seen.centre - seen.crosshair);
  if (seen.in_range && (seen.beam_ring || off < seen.bracket)) hold(bindings_.fire_primary);
  if (seen.missile_ready && w.tick - last_missile_ >= seconds_to_ticks(w, 0.5))
    tap(bindings_.fire_secondary), last_missile_ = w.tick;
  if (seen.plasma && glm::length(seen.aim - seen.crosshair) < seen.bracket && seen.distance < 1000)
    hold(bindings_.fire_secondary);
  // A torpedo: launched within 900 m with the crosshair on the brackets, one at a time.
  if (seen.torpedo && seen.target_has_parts && seen.distance < 900 && off < seen.bracket &&
      w.tick - last_missile_ >= seconds_to_ticks(w, 1.0))
    tap(bindings_.fire_secondary), last_missile_ = w.tick;
}

void HumanPilot::act(const World& w, InputFrame& in, std::vector<Command>& commands) {
  seen_.push_back(look(w));
  while (seen_.size() > delay_ + 1) seen_.pop_front();
  // What it saw a reaction time ago is what it acts on now.
  const Sight& seen = seen_.front();
  devices_ = InputState{};
  glm::dvec2 move(0.0);
  if (seen.flying && now().flying) {
    // Behind the own hull the target is not seen, but its brackets are drawn over the hull:
    // the hand still pulls toward them (fire() holds).
    start_break(w, seen);
    if (w.tick < break_until_) move = sweep_toward(break_dir_) * skill_.hand_speed;
    else if (follow_nav(seen) && seen.nav_on_screen) {
      Sight to_nav = seen;
      to_nav.aim = seen.nav_at;
      move = track(w, to_nav);
    } else if (follow_nav(seen)) move = sweep_toward(seen.nav_arrow);
    else if (seen.target && seen.on_screen) move = track(w, seen);
    else if (seen.target && !seen.on_screen) move = sweep_toward(seen.arrow);
    else if (!seen.target && seen.hostile_blip) move = sweep_toward(radar_direction(seen));
    choose_keys(w, seen);
    hunt_named_target(w, seen);
    if (!seen.prompt.empty()) train(w, seen, move);
    pick_subsystem(w, seen);
    order_wing(w, seen);
    if (w.tick < break_until_ && seen.energy > 0.15) hold(bindings_.afterburner);
    fire(w, seen);
  }
  moves_.push_back(move);
  while (moves_.size() > delay_) moves_.pop_front();
  devices_.mouse_dx = move.x;
  devices_.mouse_dy = move.y;
  input_.sample(devices_);
  in = input_.take_frame(1);
  commands = input_.take_commands();
  for (AppAction a : input_.take_actions()) {
    if (a == AppAction::ToggleCamera) commands.push_back(Command::CameraToggle);
    if (a == AppAction::TogglePadlock) commands.push_back(Command::CameraPadlock);
  }
}

}  // namespace arc
