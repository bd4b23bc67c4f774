// Team colours on hulls and exhausts, looked up in the level's table.
#include "game/render/team_colors.h"

#include <algorithm>
#include <utility>

#include "game/sim/world.h"

namespace arc {
namespace {

// How far an exhaust particle's colour moves toward the team colour (at the same brightness):
// enough to tell the teams apart by their engines, not so far that the plume loses its fade.
constexpr float kExhaustTint = 0.75f;

}  // namespace

glm::vec4 ship_team_color(const World& w, const Ship& s) {
  const auto it = w.level.team_colors.find(w.team_name(s.team));
  if (it == w.level.team_colors.end()) return glm::vec4(0.0f);
  return glm::vec4(glm::vec3(it->second), 1.0f);
}

void tint_exhausts(const World& w, std::vector<ParticleInstance>& particles) {
  std::vector<std::pair<uint32_t, glm::vec3>> tint;  // exhaust cluster → team colour, sorted
  for (const Ship& s : w.ships) {
    const glm::vec4 team = ship_team_color(w, s);
    if (!s.alive || team.a <= 0.0f) continue;
    for (const EffectHandle& e : s.exhaust_fx)
      for (ClusterHandle h : e.clusters) tint.emplace_back(h.index, glm::vec3(team));
  }
  if (tint.empty()) return;
  std::sort(tint.begin(), tint.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (ParticleInstance& p : particles) {
    const auto it = std::lower_bound(tint.begin(), tint.end(), p.cluster,
                                     [](const auto& entry, uint32_t cluster) { return entry.first < cluster; });
    if (it == tint.end() || it->first != p.cluster) continue;
    const float brightness = std::max(p.color[0], std::max(p.color[1], p.color[2]));  // premultiplied, like rgb
    for (int c = 0; c < 3; ++c) p.color[c] += (it->second[c] * brightness - p.color[c]) * kExhaustTint;
  }
}

}  // namespace arc
