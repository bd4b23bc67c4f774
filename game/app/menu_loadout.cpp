// game/app/menu_loadout.cpp — the briefing's ship and loadout choice: the ships a level's
// "loadout" block offers that the player has unlocked (the campaign's unlocks, campaign.h), each
// with the loadouts it can fly, the level's suggestion first chosen, and the choice carried by
// the Launch request; the locked ones named with the mission that opens them.
#include <algorithm>

#include "game/app/campaign.h"
#include "game/app/menu.h"
#include "game/app/menu_items.h"

namespace arc {

std::vector<ShipChoice> Menu::offered_ships() const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  std::vector<ShipChoice> out;
  if (!m) return out;
  for (const ShipChoice& c : m->ships)
    if (ship_open(c.name)) out.push_back(c);
  return out;
}

bool Menu::ship_open(const std::string& ship) const {
  if (!unlocked_ships_.empty()) return std::find(unlocked_ships_.begin(), unlocked_ships_.end(), ship) != unlocked_ships_.end();
  return ship_locked_by(catalog_, files_.progress, ship) == nullptr;
}

std::string Menu::locked_line(const std::vector<std::string>& ships) const {
  std::string out;
  for (const std::string& ship : ships) {
    if (ship_open(ship)) continue;
    const MissionInfo* by = ship_locked_by(catalog_, files_.progress, ship);
    out += (out.empty() ? "Locked: " : ", ") + ship;
    if (by) out += " (win Campaign " + std::to_string(by->campaign) + ". " + by->title + ")";
  }
  return out;
}

std::string Menu::quick_player() const {
  if (ship_open(quick_.player)) return quick_.player;
  if (ship_open("viper")) return "viper";
  for (const std::string& f : quick_classes_.fighters)
    if (ship_open(f)) return f;
  return quick_.player;
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
  std::vector<std::string> names;
  for (const ShipChoice& c : m->ships) names.push_back(c.name);
  if (const std::string locked = locked_line(names); !locked.empty()) p.lines.push_back(locked);
}

MenuRequest Menu::launch_request(const std::string& level) const {
  MenuRequest r(MenuRequest::Kind::Launch, level, difficulty_);
  r.ship = chosen_ship();
  r.loadout = chosen_loadout();
  return r;
}

}  // namespace arc
