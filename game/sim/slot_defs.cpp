// game/sim/slot_defs.cpp — the optional "slots" list of a level: the ships pilots may take in a
// network match, each naming one ship of "ships"; a slot nobody takes is flown by the AI.
#include <set>

#include "game/sim/def_parsing.h"
#include "game/sim/defs.h"

namespace arc::defs_internal {

void parse_slots(JsonObject& r, LevelDef& L) {
  r.check_list_length("slots", kMaxLevelSlots);
  std::set<std::string> taken;
  for (JsonObject s : r.objects("slots")) {
    SlotDef d;
    d.ship = s.require_string("ship");
    s.finish();
    const ShipSpawnDef* ship = nullptr;
    for (const ShipSpawnDef& e : L.ships)
      if (e.name == d.ship) ship = &e;
    if (!ship) s.fail_key("ship", "'" + s.key_path("ship") + "' names no ship of 'ships': \"" + d.ship + "\"");
    if (!taken.insert(d.ship).second) s.fail_key("ship", "ship \"" + d.ship + "\" has two slots; a ship takes at most one");
    if (ship->inactive) s.fail_key("ship", "a slot needs a ship present from the start, and \"" + d.ship + "\" is 'inactive'");
    if (ship->ai != AiKind::Fighter && ship->ai != AiKind::None)
      s.fail_key("ship", "a slot's ship must be the player or a fighter ('ai': \"fighter\"); \"" + d.ship + "\" is not");
    d.team = ship->team;
    L.slots.push_back(std::move(d));
  }
  if (L.slots.empty() && r.has("slots")) r.fail_key("slots", "'slots' lists at least one {\"ship\": NAME}");
  if (!L.slots.empty()) {
    bool player_first = false;
    for (const ShipSpawnDef& e : L.ships)
      if (e.player) player_first = e.name == L.slots.front().ship;
    bool any_player = false;
    for (const ShipSpawnDef& e : L.ships) any_player = any_player || e.player;
    if (any_player && !player_first)
      r.fail_key("slots", "the first slot must be the player's ship (the host flies it)");
  }
}

}  // namespace arc::defs_internal
