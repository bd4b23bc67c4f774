// game/sim/capital_defs.cpp — a ship class's "turrets", "subsystems", "breakup" and "torpedo"
// blocks (capital ships and the weapon that hurts only them), and loadout names.
#include <cmath>
#include <set>

#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc {
using namespace defs_internal;

namespace {

constexpr double kPartLimit = 2000.0;  // metres: a part's position on its hull, each axis

// A part's name: required, unique within its ship (the HUD and mission events name parts by it).
std::string part_name(JsonObject& o, std::set<std::string>& names) {
  const std::string n = o.require_string("name");
  if (n.empty() || n.size() > 32) o.fail_key("name", "'" + o.key_path("name") + "' must be 1 to 32 characters");
  if (!names.insert(n).second)
    o.fail_key("name", "'" + o.key_path("name") + "': a turret or subsystem named '" + n + "' is already on this ship");
  return n;
}

TurretDef parse_turret(JsonObject& o, std::set<std::string>& names) {
  TurretDef t;
  t.name = part_name(o, names);
  t.kind = o.choice("kind", "beam", {"beam", "flak"}) == "flak" ? TurretKind::Flak : TurretKind::Beam;
  t.position = o.vec3("position", glm::dvec3(0.0), -kPartLimit, kPartLimit);
  const glm::dvec3 f = o.vec3("facing", glm::dvec3(0, 1, 0), -1.0, 1.0);
  const double len = std::sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
  if (len < 1e-3) o.fail_key("facing", "'" + o.key_path("facing") + "' must point somewhere (not [0, 0, 0])");
  t.facing = f / len;
  t.arc = o.number("arc", 90.0, 1.0, 180.0);
  t.range = o.number("range", t.kind == TurretKind::Flak ? 700.0 : 750.0, 1.0, 1.0e5);
  t.damage = o.number("damage", t.kind == TurretKind::Flak ? 12.0 : 20.0, 0.0, kHuge);
  t.cooldown = o.number("cooldown", t.kind == TurretKind::Flak ? 0.5 : 1.5, 1.0 / 60.0, 600.0);
  t.spread = o.number("spread", t.kind == TurretKind::Flak ? 0.04 : 0.01, 0.0, 1.0);
  t.burst_radius = o.number("burst_radius", 25.0, 0.1, 1000.0);
  t.hull = o.number("hull", 150.0, 1.0, kHuge);
  t.radius = o.number("radius", 8.0, 0.1, 1000.0);
  o.finish();
  return t;
}

SubsystemDef parse_subsystem(JsonObject& o, std::set<std::string>& names) {
  SubsystemDef s;
  s.name = part_name(o, names);
  const std::string k = o.choice("kind", "other", {"engine", "shield_generator", "other"});
  s.kind = k == "engine" ? SubsystemKind::Engine : k == "shield_generator" ? SubsystemKind::ShieldGenerator : SubsystemKind::Other;
  s.position = o.vec3("position", glm::dvec3(0.0), -kPartLimit, kPartLimit);
  s.radius = o.number("radius", 10.0, 0.1, 1000.0);
  s.hull = o.number("hull", 300.0, 1.0, kHuge);
  o.finish();
  return s;
}

}  // namespace

const char* weapon_name(WeaponKind k) {
  switch (k) {
    case WeaponKind::Beam: return "beam";
    case WeaponKind::Plasma: return "plasma";
    case WeaponKind::Missile: return "missile";
    case WeaponKind::Torpedo: return "torpedo";
  }
  return "beam";
}

bool ShipClassDef::has(WeaponKind k) const {
  switch (k) {
    case WeaponKind::Beam: return !beam.mounts.empty();
    case WeaponKind::Plasma: return plasma.present;
    case WeaponKind::Missile: return missile.present;
    case WeaponKind::Torpedo: return torpedo.present;
  }
  return false;
}

void defs_internal::parse_capital(JsonObject& r, ShipClassDef& c) {
  std::set<std::string> names;
  r.check_list_length("turrets", kMaxShipPoints);
  r.check_list_length("subsystems", kMaxShipPoints);
  for (JsonObject& t : r.objects("turrets")) c.turrets.push_back(parse_turret(t, names));
  for (JsonObject& s : r.objects("subsystems")) c.subsystems.push_back(parse_subsystem(s, names));
  if (auto b = r.get("breakup")) {
    JsonObject o = b->object();
    c.breakup.stages = static_cast<int>(o.integer("stages", 5, 0, 32));
    c.breakup.seconds = o.number("seconds", 4.0, 0.1, 60.0);
    c.breakup.final_scale = o.number("final_scale", 8.0, 0.1, 100.0);
    c.breakup.spin = o.number("spin", 6.0, 0.0, 360.0);
    o.finish();
  }
}

}  // namespace arc
