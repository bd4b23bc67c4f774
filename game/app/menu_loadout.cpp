// game/app/menu_loadout.cpp — the briefing's ship and loadout choice: the ships a level's
// "loadout" block offers that the player has unlocked, each with the loadouts it can fly, the
// level's suggestion first chosen, and the choice carried by the Launch request.
#include <algorithm>

#include "game/app/menu.h"
#include "game/app/menu_items.h"

namespace arc {

std::vector<ShipChoice> Menu::offered_ships() const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  std::vector<ShipChoice> out;
  if (!m) return out;
  for (const ShipChoice& c : m->ships)
    if (unlocked_ships_.empty() || std::find(unlocked_ships_.begin(), unlocked_ships_.end(), c.name) != unlocked_ships_.end())
      out.push_back(c);
  return out;
}

std::vector<Menu::Item> Menu::briefing_items() const {
  if (offered_ships().empty()) return {Item::Launch, Item::Difficulty, Item::Back};
  return {Item::Launch, Item::Ship, Item::Loadout, Item::Difficulty, Item::Back};
}

// The suggestion where it is offered, else the first ship and its first loadout.
void Menu::reset_choice() {
  ship_choice_ = loadout_choice_ = 0;
  const MissionInfo* m = find_mission(catalog_, chosen_);
  const std::vector<ShipChoice> ships = offered_ships();
  if (!m) return;
  for (size_t i = 0; i < ships.size(); ++i) {
    if (ships[i].name != m->suggested_ship) continue;
    ship_choice_ = int(i);
    const auto& l = ships[i].loadouts;
    const auto it = std::find(l.begin(), l.end(), m->suggested_loadout);
    if (it != l.end()) loadout_choice_ = int(it - l.begin());
  }
}

std::string Menu::chosen_ship() const {
  const std::vector<ShipChoice> ships = offered_ships();
  return ship_choice_ < int(ships.size()) ? ships[size_t(ship_choice_)].name : "";
}

std::string Menu::chosen_loadout() const {
  const std::vector<ShipChoice> ships = offered_ships();
  if (ship_choice_ >= int(ships.size())) return "";
  const auto& l = ships[size_t(ship_choice_)].loadouts;
  return loadout_choice_ < int(l.size()) ? l[size_t(loadout_choice_)] : "";
}

std::string Menu::choice_label(Item item) const {
  if (item == Item::Ship) return "Ship: < " + chosen_ship() + " >";
  return "Loadout: < " + chosen_loadout() + " >";
}

void Menu::adjust_choice(Item item, int step) {
  const std::vector<ShipChoice> ships = offered_ships();
  if (ships.empty()) return;
  const int n = int(ships.size());
  if (item == Item::Ship) {
    const std::string loadout = chosen_loadout();
    ship_choice_ = ((ship_choice_ + step) % n + n) % n;
    // Keep the loadout when the new ship flies it too.
    const auto& l = ships[size_t(ship_choice_)].loadouts;
    const auto it = std::find(l.begin(), l.end(), loadout);
    loadout_choice_ = it != l.end() ? int(it - l.begin()) : 0;
    return;
  }
  const int m = int(ships[size_t(ship_choice_)].loadouts.size());
  loadout_choice_ = ((loadout_choice_ + step) % m + m) % m;
}

void Menu::fill_choice_lines(MenuPage& p) const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  if (!m || offered_ships().empty()) return;
  p.lines.push_back("Suggested: " + m->suggested_ship + ", " + m->suggested_loadout +
                    "   (ship and loadout: Left/Right on their rows)");
}

MenuRequest Menu::launch_request(const std::string& level) const {
  MenuRequest r(MenuRequest::Kind::Launch, level, difficulty_);
  r.ship = chosen_ship();
  r.loadout = chosen_loadout();
  return r;
}

}  // namespace arc
