#include <gtest/gtest.h>

#include "core/error.h"
#include "core/settings.h"

TEST(Settings, DefaultsAreDocumentedAndValid) {
  auto s = arc::Settings::defaults();
  EXPECT_EQ(s.choice("render.sorting"), "full");
  EXPECT_EQ(s.integer("particles.budget"), 200000);
  EXPECT_NE(s.describe().find("render.soft_edges"), std::string::npos);
}

TEST(Settings, SetChecksKeyTypeAndRange) {
  auto s = arc::Settings::defaults();
  s.set_from_text("render.scale=0.5", "--set");
  EXPECT_DOUBLE_EQ(s.number("render.scale"), 0.5);
  EXPECT_THROW(s.set_from_text("render.scale=9", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.scale=nan", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.sorting=random", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("no.such=1", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.scale", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("particles.budget=1.5", "--set"), arc::InputError);
}

TEST(Settings, EveryShippedPresetApplies) {
  std::string path = std::string(ARCFIRE_SOURCE_DIR) + "/assets/settings/quality.json";
  auto names = arc::Settings::preset_names(path);
  ASSERT_EQ(names.size(), 4u);
  for (const auto& n : names) {
    auto s = arc::Settings::defaults();
    EXPECT_NO_THROW(s.apply_preset_file(path, n)) << n;
  }
  auto s = arc::Settings::defaults();
  s.apply_preset_file(path, "low");
  EXPECT_EQ(s.choice("render.soft_edges"), "off");
  EXPECT_THROW(s.apply_preset_file(path, "ultra"), arc::InputError);
}
