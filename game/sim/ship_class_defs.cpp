// game/sim/ship_class_defs.cpp — ship classes and their weapons from assets/ships/*.json.
#include <filesystem>
#include <system_error>

#include "core/data_layers.h"
#include "core/input_file.h"
#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc {
using namespace defs_internal;

void defs_internal::require_named_file(const JsonValue& v, const std::string& named, const std::string& root_dir,
                                       const char* what) {
  namespace fs = std::filesystem;
  const std::string file = fs::path(named).is_absolute() ? named : data_file(root_dir, named);
  const std::string problem = input_path_problem(file);
  if (problem.empty()) return;
  const std::string why = problem == "not found" ? "no such file" : problem;
  std::string message = "'";
  message += v.name();
  message += "' names ";
  message += what;
  message += ' ';
  message += file;
  message += ": ";
  message += why;
  v.fail(message);
}

namespace {

ProjectileWeaponDef projectile_weapon(JsonObject& o, bool homing, bool torpedo = false) {
  ProjectileWeaponDef w;
  w.present = true;
  w.hardpoints = points(o, "hardpoints", 100.0);
  if (w.hardpoints.empty()) o.fail_key("hardpoints", "'" + o.key_path("hardpoints") + "' must list at least one [x, y, z]");
  w.speed = o.number("speed", torpedo ? 120.0 : homing ? 220.0 : 450.0, 1.0, 5000.0);
  w.damage = o.number("damage", torpedo ? 400.0 : homing ? 45.0 : 18.0, 0.0, kHuge);
  w.energy = o.number("energy", homing ? 15.0 : 6.0, 0.0, kHuge);
  w.cooldown = o.number("cooldown", homing ? 2.0 : 0.25, 1.0 / 240.0, 600.0);
  w.lifetime = o.number("lifetime", homing ? 8.0 : 3.0, 0.05, 600.0);
  w.turn_rate = homing ? o.number("turn_rate", 120.0, 0.0, 3600.0) : 0.0;
  w.hit_radius = o.number("hit_radius", 1.0, 0.0, 1000.0);
  if (homing) {
    w.lock_time = o.number("lock_time", 1.75, 0.0, 60.0);
    w.lock_cone = o.number("lock_cone", 13.0, 0.5, 90.0);
    w.lock_range = o.number("lock_range", 1200.0, 1.0, 1.0e5);
    w.seeker_cone = o.number("seeker_cone", 50.0, 1.0, 180.0);
  }
  o.finish();
  return w;
}

ShipClassDef parse_ship_class_doc(const std::shared_ptr<const JsonDoc>& doc, const std::string& name,
                                  const std::string& root_dir) {
  JsonObject r = root_of(doc);
  ShipClassDef c;
  c.name = name;
  c.path = doc->path();
  const JsonValue model = r.require("model");
  c.model = model.string();
  c.mass = r.require_number("mass", 1.0, 1.0e9);
  c.thrust = r.require_number("thrust", 0.0, 1.0e12);
  c.strafe_thrust = r.number("strafe_thrust", c.thrust * 0.5, 0.0, 1.0e12);
  glm::dvec3 turn = r.vec3("turn_rates", glm::dvec3(90.0, 90.0, 120.0), 0.0, 3600.0);
  c.turn_rate[0] = turn.x;
  c.turn_rate[1] = turn.y;
  c.turn_rate[2] = turn.z;
  c.turn_response = r.number("turn_response", 6.0, 0.1, 100.0);
  c.max_speed = r.require_number("max_speed", 1.0, 1.0e5);
  c.reverse_fraction = r.number("reverse_fraction", 0.3, 0.0, 1.0);
  c.afterburner_speed = r.number("afterburner_speed", 1.6, 1.0, 10.0);
  c.afterburner_energy = r.number("afterburner_energy", 20.0, 0.0, kHuge);
  c.hull = r.require_number("hull", 1.0, kHuge);
  c.shield = r.number("shield", 0.0, 0.0, kHuge);
  c.shield_regen = r.number("shield_regen", 10.0, 0.0, kHuge);
  c.shield_regen_delay = r.number("shield_regen_delay", 3.0, 0.0, 3600.0);
  c.energy = r.number("energy", 100.0, 0.0, kHuge);
  c.energy_regen = r.number("energy_regen", 15.0, 0.0, kHuge);
  c.collision_radius = r.require_number("collision_radius", 0.1, 1000.0);
  c.shield_radius = r.number("shield_radius", c.collision_radius * 1.3, 0.1, 1000.0);
  if (c.shield_radius < c.collision_radius)
    r.fail_key("shield_radius", "'" + r.key_path("shield_radius") + "' must be at least 'collision_radius' (" +
                                    std::to_string(c.collision_radius) + ")");
  JsonObject beam = r.require_object("beam");
  c.beam.mounts = points(beam, "mounts", 100.0);
  if (c.beam.mounts.empty()) beam.fail_key("mounts", "'" + beam.key_path("mounts") + "' must list at least one [x, y, z]");
  c.beam.range = beam.number("range", 600.0, 1.0, 1.0e5);
  c.beam.damage_per_second = beam.number("damage_per_second", 40.0, 0.0, kHuge);
  c.beam.energy_per_second = beam.number("energy_per_second", 25.0, 0.0, kHuge);
  beam.finish();
  if (auto m = r.get("missile")) {
    JsonObject o = m->object();
    c.missile = projectile_weapon(o, true);
  }
  if (auto p = r.get("plasma")) {
    JsonObject o = p->object();
    c.plasma = projectile_weapon(o, false);
  }
  if (auto t = r.get("torpedo")) {
    JsonObject o = t->object();
    c.torpedo = projectile_weapon(o, true, true);
  }
  if (auto cm = r.get("countermeasures")) {
    JsonObject o = cm->object();
    c.countermeasures.count = static_cast<int>(o.integer("count", 8, 0, 100));
    c.countermeasures.cooldown = o.number("cooldown", 1.0, 1.0 / 60.0, 60.0);
    c.countermeasures.lifetime = o.number("lifetime", 3.0, 0.1, 30.0);
    c.countermeasures.decoy_chance = o.number("decoy_chance", 0.7, 0.0, 1.0);
    o.finish();
  }
  c.exhausts = points(r, "exhausts", 1000.0, kMaxShipExhausts);
  parse_capital(r, c);
  r.finish();
  if (!root_dir.empty()) require_named_file(model, c.model, root_dir, "model");  // what the file names, once it is whole
  return c;
}

}  // namespace

ShipClassDef load_ship_class(const std::string& path, const std::string& name, const std::string& root_dir) {
  return parse_ship_class_doc(JsonDoc::load_file(path), name, root_dir);
}

ShipClassDef parse_ship_class(const std::string& text, const std::string& path, const std::string& name) {
  return parse_ship_class_doc(JsonDoc::parse(text, path), name, "");
}

}  // namespace arc
