// game/sim/damage.cpp — damage (shield first, then hull), deaths, explosions and splash damage.
#include "game/sim/damage.h"

#include <algorithm>

#include "game/sim/beams.h"
#include "game/sim/capital.h"
#include "game/sim/effects.h"
#include "game/sim/geometry.h"
#include "game/sim/shields.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kExplosionMemorySeconds = 1.0;

void kill_ship(World& w, Ship& s) {
  s.alive = false;
  s.death_tick = w.tick;
  s.hull = 0;
  stop_beam(w, s);
  w.particles->destroy_owner(s.particle_owner);
  s.shield_fx = {};
  s.exhaust_fx.clear();
  if (!start_breakup(w, s)) {
    SpawnParams p;
    p.position = s.position;
    p.velocity = s.velocity;
    p.scale = s.cls->collision_radius / 8.0;
    p.priority = 2;
    spawn_fx(w, w.fx.ship_explosion, p);
    w.explosions.push_back({s.position, w.tick, s.cls->collision_radius * 6.0});
  }
  if (s.last_attacker && s.last_attacker != s.id) w.ship(s.last_attacker).kills++;
  if (!w.level.splash) return;
  for (Ship& o : w.ships) {
    if (!o.alive) continue;
    double d = safe_len(o.position - s.position);
    if (d >= w.level.splash_radius) continue;
    double falloff = 1.0 - d / w.level.splash_radius;
    apply_damage(w, o, w.level.splash_damage * falloff, o.position, s.last_attacker);
  }
}

}  // namespace

void apply_damage(World& w, Ship& t, double amount, const glm::dvec3& point, ShipId attacker, bool parts) {
  if (!t.alive || amount <= 0) return;
  t.last_hit_tick = w.tick;
  if (attacker) t.last_attacker = attacker;
  const double taken = std::min(amount, std::max(t.shield, 0.0) + std::max(t.hull, 0.0));
  t.stats.damage_taken += taken;
  if (attacker && attacker != t.id) w.ship(attacker).stats.damage_dealt += taken;
  double to_shield = std::min(t.shield, amount);
  t.shield -= to_shield;
  t.hull -= amount - to_shield;
  if (parts && !t.parts.empty()) damage_parts(w, t, point, amount - to_shield, attacker);
  if (to_shield > 0 && !t.shield_fx.clusters.empty()) {
    if (t.shield_flash_tick != w.tick)
      for (ClusterHandle ch : t.shield_fx.clusters) w.particles->flash(ch, point, kFlashSeconds);
    t.shield_flash_tick = w.tick;
  }
}

void resolve_deaths(World& w) {
  // Splash damage can kill more ships; repeat until nothing changes, always in id order.
  bool again = true;
  while (again) {
    again = false;
    for (Ship& s : w.ships)
      if (s.alive && s.hull <= 0) kill_ship(w, s), again = true;
  }
  for (Ship& s : w.ships)
    if (s.target && !w.ship(s.target).alive) s.target = {};
  std::erase_if(w.explosions, [&](const ExplosionEvent& e) {
    return w.tick - e.tick > seconds_to_ticks(w, kExplosionMemorySeconds);
  });
}

}  // namespace arc
