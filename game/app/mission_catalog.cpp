// The menu's list of missions and effect scenes, read from the levels' "mission" blocks.
#include "game/app/mission_catalog.h"

#include <algorithm>
#include <filesystem>

#include "core/error.h"

namespace arc {

std::vector<MissionInfo> load_mission_catalog(const std::string& levels_dir, const std::string& root_dir) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(levels_dir))
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  std::vector<MissionInfo> out;
  std::vector<std::string> where;
  for (const std::string& f : files) {
    const LevelDef L = load_level_def(f, root_dir);
    if (!L.mission.present) continue;
    const MissionDef& m = L.mission;
    for (size_t i = 0; i < out.size(); ++i)
      if (out[i].category == m.category && out[i].order == m.order)
        throw InputError(m.order_where + ": 'order' " + std::to_string(m.order) + " is already taken by " +
                         out[i].path + " (" + where[i] + "); allowed: an order no other level of its category has");
    out.push_back({f, m.title, m.briefing, m.objective, m.order, m.category});
    where.push_back(m.order_where);
  }
  std::stable_sort(out.begin(), out.end(), [](const MissionInfo& a, const MissionInfo& b) {
    return a.category != b.category ? a.category < b.category : a.order < b.order;
  });
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
    if (m.category == MissionCategory::Mission && m.order > current->order) return &m;
  return nullptr;
}

}  // namespace arc
