// game/sim/loadout.cpp — loadouts ("beam+torpedo"), a level's "loadout" block (what the briefing
// offers) and the player's choice applied to the level before it starts.
#include "game/sim/loadout.h"

#include <algorithm>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/input_file.h"
#include "game/sim/def_parsing.h"

namespace arc {
using namespace defs_internal;

namespace {

constexpr WeaponKind kWeapons[] = {WeaponKind::Beam, WeaponKind::Plasma, WeaponKind::Missile, WeaponKind::Torpedo};

bool weapon_of(const std::string& name, WeaponKind& out) {
  for (WeaponKind k : kWeapons)
    if (name == weapon_name(k)) return out = k, true;
  return false;
}

bool class_name_ok(const std::string& n) {
  return !n.empty() && n.size() <= 64 && n.find_first_of("/\\.+") == std::string::npos;
}

std::string class_file(const std::string& root_dir, const std::string& name) {
  return data_file(root_dir, "assets/ships/" + name + ".json");
}

}  // namespace

bool parse_loadout(const std::string& text, Loadout& out, std::string& why) {
  const size_t plus = text.find('+');
  if (plus == std::string::npos) {
    why = "a loadout is PRIMARY+SECONDARY (e.g. beam+torpedo), got \"" + text + "\"";
    return false;
  }
  Loadout l;
  if (!weapon_of(text.substr(0, plus), l.primary) || !weapon_of(text.substr(plus + 1), l.secondary)) {
    why = "a loadout names two weapons of beam, plasma, missile or torpedo, got \"" + text + "\"";
    return false;
  }
  out = l;
  return true;
}

std::string loadout_text(const Loadout& l) { return std::string(weapon_name(l.primary)) + "+" + weapon_name(l.secondary); }

std::string loadout_problem(const ShipClassDef& c, const Loadout& l) {
  if (l.primary != WeaponKind::Beam && l.primary != WeaponKind::Plasma)
    return std::string("the primary bank is the beam or plasma, not ") + weapon_name(l.primary);
  if (l.secondary == WeaponKind::Beam) return "the secondary bank is plasma, missile or torpedo, not the beam";
  if (l.primary == l.secondary) return "the two banks must hold different weapons";
  for (WeaponKind k : {l.primary, l.secondary})
    if (!c.has(k)) return "ship class '" + c.name + "' carries no " + weapon_name(k);
  return "";
}

ShipClassDef apply_loadout(const ShipClassDef& c, const Loadout& l) {
  ShipClassDef out = c;
  const auto keep = [&](WeaponKind k) { return l.primary == k || l.secondary == k; };
  if (!keep(WeaponKind::Plasma)) out.plasma.present = false;
  if (!keep(WeaponKind::Missile)) out.missile.present = false;
  if (!keep(WeaponKind::Torpedo)) out.torpedo.present = false;
  out.primary_plasma = l.primary == WeaponKind::Plasma;
  out.name = c.name + "+" + loadout_text(l);
  return out;
}

void defs_internal::parse_loadout_choice(JsonObject& r, LevelDef& L, const std::string& root_dir) {
  auto v = r.get("loadout");
  if (!v) return;
  JsonObject o = v->object();
  LoadoutChoiceDef& d = L.loadout;
  d.present = true;
  o.check_list_length("ships", 16);
  o.check_list_length("weapons", 4);
  JsonValue ships = o.require("ships");
  for (const JsonValue& s : ships.array()) {
    const std::string n = s.string();
    if (!class_name_ok(n)) s.fail("'" + s.name() + "' must be a ship class name (a file stem in assets/ships/)");
    if (!root_dir.empty() && !input_path_exists(class_file(root_dir, n)))
      s.fail("'" + s.name() + "': ship class '" + n + "' not found: no file " + class_file(root_dir, n));
    if (std::find(d.ships.begin(), d.ships.end(), n) != d.ships.end()) s.fail("'" + s.name() + "' lists '" + n + "' twice");
    d.ships.push_back(n);
  }
  if (d.ships.empty()) ships.fail("'" + ships.name() + "' must list at least one ship class");
  JsonValue weapons = o.require("weapons");
  for (const JsonValue& w : weapons.array()) {
    WeaponKind k;
    if (!weapon_of(w.string(), k)) w.fail("'" + w.name() + "' must be beam, plasma, missile or torpedo");
    if (std::find(d.weapons.begin(), d.weapons.end(), k) != d.weapons.end()) w.fail("'" + w.name() + "' is listed twice");
    d.weapons.push_back(k);
  }
  if (d.weapons.size() < 2) weapons.fail("'" + weapons.name() + "' must list at least two weapons (one per bank)");
  JsonValue ship = o.require("suggested_ship");
  d.suggested_ship = ship.string();
  if (std::find(d.ships.begin(), d.ships.end(), d.suggested_ship) == d.ships.end())
    ship.fail("'" + ship.name() + "' must be one of 'ships', got \"" + d.suggested_ship + "\"");
  JsonValue sl = o.require("suggested_loadout");
  std::string why;
  if (!parse_loadout(sl.string(), d.suggested, why)) sl.fail("'" + sl.name() + "': " + why);
  for (WeaponKind k : {d.suggested.primary, d.suggested.secondary})
    if (std::find(d.weapons.begin(), d.weapons.end(), k) == d.weapons.end())
      sl.fail("'" + sl.name() + "' names " + weapon_name(k) + ", which 'weapons' does not allow");
  if (!root_dir.empty()) {
    const ShipClassDef c = load_ship_class(class_file(root_dir, d.suggested_ship), d.suggested_ship, root_dir);
    const std::string problem = loadout_problem(c, d.suggested);
    if (!problem.empty()) sl.fail("'" + sl.name() + "': " + problem);
  }
  o.finish();
}

void apply_player_choice(LevelDef& L, const std::string& ship, const std::string& loadout, const std::string& root_dir) {
  if (ship.empty() && loadout.empty()) return;
  ShipSpawnDef* player = nullptr;
  for (ShipSpawnDef& d : L.ships)
    if (d.player) player = &d;
  if (!player) throw InputError(L.path + ": the level has no player ship to choose a ship or loadout for");
  std::string cls = player->ship_class;
  if (!ship.empty()) {
    if (!class_name_ok(ship)) throw InputError("--ship: '" + ship + "' must be a ship class name (a file stem in assets/ships/)");
    const std::string file = class_file(root_dir, ship);
    if (!input_path_exists(file)) throw InputError("--ship: ship class '" + ship + "' not found: no file " + file);
    if (!L.classes.count(ship)) L.classes.emplace(ship, std::make_shared<const ShipClassDef>(load_ship_class(file, ship, root_dir)));
    cls = ship;
  }
  if (!loadout.empty()) {
    Loadout l;
    std::string why;
    if (!parse_loadout(loadout, l, why)) throw InputError("--loadout: " + why);
    const ShipClassDef& base = *L.classes.at(cls);
    why = loadout_problem(base, l);
    if (!why.empty()) throw InputError("--loadout: " + why);
    ShipClassDef armed = apply_loadout(base, l);
    cls = armed.name;
    L.classes.emplace(cls, std::make_shared<const ShipClassDef>(std::move(armed)));
  }
  player->ship_class = cls;
}

}  // namespace arc
