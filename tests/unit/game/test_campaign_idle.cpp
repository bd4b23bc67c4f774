// tests/unit/game/test_campaign_idle.cpp — a campaign mission is never won by a player who does
// nothing: flown with no input for five minutes (or until decided), none ends in victory, so the
// player's own kills and strikes decide each mission.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/data_root.h"
#include "game/sim/game.h"
#include "game/sim/world.h"

namespace arc {
namespace {

// The one exception: the escort is won by its wingman and the freighter alone. Raiders enough to
// beat them also beat the human-like pilot, which deals almost no damage there (docs/pilot.md).
constexpr const char* kOpen = "03_escort.json";

TEST(CampaignIdle, NoMissionIsWonWithoutInput) {
  std::vector<std::string> levels;
  for (const auto& e : std::filesystem::directory_iterator(data_root() + "/levels/campaign"))
    if (e.path().extension() == ".json" && e.path().filename() != "campaign.json" && e.path().filename() != kOpen)
      levels.push_back(e.path().string());
  std::sort(levels.begin(), levels.end());
  ASSERT_GE(levels.size(), 6u);
  for (const std::string& level : levels) {
    GameOptions o;
    o.root_dir = data_root();
    Game g = Game::load_level(level, o);
    const World& w = g.world();
    const int64_t limit = seconds_to_ticks(w, 300.0);
    while (w.tick < limit && w.outcome == Outcome::Undecided) g.step(InputFrame{});
    EXPECT_NE(w.outcome, Outcome::Victory) << level << " is won at tick " << w.outcome_tick << " by a player who does nothing";
  }
}

}  // namespace
}  // namespace arc
