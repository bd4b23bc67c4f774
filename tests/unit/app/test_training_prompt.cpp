// The training prompt names the keys the player has bound: the default bindings' keys, and a
// remapped key as remapped (game/app/key_remap.h key_names, game/render/hud_training.h).
#include <gtest/gtest.h>

#include <string>

#include "core/data_root.h"
#include "game/app/key_remap.h"
#include "game/render/hud_layout.h"
#include "game/render/hud_training.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "platform/platform.h"

namespace arc {
namespace {

const std::string kRoot = arc::data_root();

// Every text the HUD draws for the training level at its first step with a target to pick.
std::string hud_texts(const Bindings& b) {
  GameOptions o;
  o.root_dir = kRoot;
  Game g = Game::load_level(kRoot + "/levels/training.json", o);
  World& w = g.world_mut();
  w.training->step = 3;  // "Press {target_nearest} to target it"
  HudState state;
  state.key_names = key_names(b);
  HudLayer layer;
  CameraView cam;
  layout_hud(w, cam, state, 1.0, 1280, 720, layer);
  std::string all;
  for (const HudText& t : layer.texts) all += t.text + "\n";
  return all;
}

TEST(TrainingPrompt, NamesTheDefaultKeys) {
  const Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  const std::string texts = hud_texts(b);
  EXPECT_NE(texts.find("TRAINING 4/9"), std::string::npos) << texts;
  EXPECT_NE(texts.find("Press [R] to target it"), std::string::npos) << texts;
  EXPECT_EQ(texts.find('{'), std::string::npos) << "no placeholder left: " << texts;
}

TEST(TrainingPrompt, ShowsARemappedKeyAsRemapped) {
  Bindings b = load_bindings(kRoot + "/assets/settings/bindings.json");
  remap_key(b, "target_nearest", key_code("K"));
  const std::string texts = hud_texts(b);
  EXPECT_NE(texts.find("Press [K] to target it"), std::string::npos) << texts;
  EXPECT_EQ(texts.find("[R]"), std::string::npos) << texts;
}

TEST(TrainingPrompt, EveryPlaceholderOfTheShippedLevelIsAnAction) {
  GameOptions o;
  o.root_dir = kRoot;
  const Game g = Game::load_level(kRoot + "/levels/training.json", o);
  const auto names = key_names(load_bindings(kRoot + "/assets/settings/bindings.json"));
  for (const TrainingStepDef& s : g.world().level.training.steps) {
    const std::string shown = training_prompt(s.prompt, names);
    EXPECT_EQ(shown.find("no key"), std::string::npos) << shown;
    EXPECT_EQ(shown.find('{'), std::string::npos) << shown;
  }
  EXPECT_EQ(training_prompt("Hold {fire_primary} or {nothing_bound}", {{"fire_primary", "MOUSE_LEFT"}}),
            "Hold [LEFT MOUSE] or [no key: nothing bound]");
  EXPECT_EQ(training_prompt("{afterburner}", {{"afterburner", "LEFT_SHIFT"}}), "[LEFT SHIFT]");
}

}  // namespace
}  // namespace arc
