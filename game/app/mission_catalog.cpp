// The menu's list of missions and effect scenes, read from the levels' "mission" blocks.
#include "game/app/mission_catalog.h"

#include <algorithm>
#include <filesystem>

#include "core/data_layers.h"
#include "core/error.h"

namespace arc {

std::vector<MissionInfo> load_mission_catalog(const std::string& levels_dir, const std::string& root_dir) {
  // With mods in use, their levels join the folder's (a mod's file replaces the base one).
  const std::vector<std::string> files = data_files(levels_dir, "", ".json");
  std::vector<MissionInfo> out;
  std::vector<std::string> where;
  for (const std::string& f : files) {
    const LevelDef L = load_level_def(f, root_dir);
    if (!L.mission.present) continue;
    const MissionDef& m = L.mission;
    const std::string mod = data_layers().mod_of(f);
    for (size_t i = 0; i < out.size(); ++i)
      if (out[i].category == m.category && out[i].order == m.order && out[i].mod == mod)
        throw InputError(m.order_where + ": 'order' " + std::to_string(m.order) + " is already taken by " +
                         out[i].path + " (" + where[i] + "); allowed: an order no other level of its category has");
    out.push_back({f, m.title, m.briefing, m.objective, m.order, m.category, mod, 0, "", ship_choices(L, root_dir),
                   L.loadout.suggested_ship, L.loadout.present ? loadout_text(L.loadout.suggested) : ""});
    where.push_back(m.order_where);
  }
  // The game's own missions first, then each mod's apart, in the order the mods were laid.
  auto mod_rank = [](const std::string& mod) {
    const auto& mods = data_layers().mods();
    for (size_t i = 0; i < mods.size(); ++i)
      if (mods[i].name == mod) return i + 1;
    return size_t(0);
  };
  std::stable_sort(out.begin(), out.end(), [&](const MissionInfo& a, const MissionInfo& b) {
    if (a.mod != b.mod) return mod_rank(a.mod) < mod_rank(b.mod);
    return a.category != b.category ? a.category < b.category : a.order < b.order;
  });
  return out;
}

std::vector<ShipChoice> ship_choices(const LevelDef& L, const std::string& root_dir) {
  std::vector<ShipChoice> out;
  for (const std::string& name : L.loadout.ships) {
    const ShipClassDef c = load_ship_class(data_file(root_dir, "assets/ships/" + name + ".json"), name, root_dir);
    ShipChoice choice{name, {}};
    for (WeaponKind p : L.loadout.weapons)
      for (WeaponKind s : L.loadout.weapons)
        if (loadout_problem(c, {p, s}).empty()) choice.loadouts.push_back(loadout_text({p, s}));
    if (!choice.loadouts.empty()) out.push_back(std::move(choice));
  }
  return out;
}

const MissionInfo* find_mission(const std::vector<MissionInfo>& all, const std::string& path) {
  for (const MissionInfo& m : all)
    if (m.path == path) return &m;
  return nullptr;
}

const MissionInfo* next_mission(const std::vector<MissionInfo>& all, const std::string& path) {
  const MissionInfo* current = find_mission(all, path);
  if (!current || current->category != MissionCategory::Mission) return nullptr;
  for (const MissionInfo& m : all)
    if (m.category == MissionCategory::Mission && m.mod == current->mod && m.order > current->order) return &m;
  return nullptr;
}

}  // namespace arc
