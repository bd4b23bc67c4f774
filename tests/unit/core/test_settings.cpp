#include <gtest/gtest.h>

#include "core/error.h"
#include "core/settings.h"
#include "core/data_root.h"

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
  std::string path = arc::data_root() + "/assets/settings/quality.json";
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

TEST(Settings, HdrBloomExposureAndAntialiasAreValidated) {
  auto s = arc::Settings::defaults();
  // The default is the 8-bit scene (the look's passes cost more than a 60 Hz frame on llvmpipe).
  EXPECT_FALSE(s.flag("render.hdr"));
  EXPECT_EQ(s.choice("render.bloom"), "off");
  EXPECT_EQ(s.choice("render.antialias"), "off");
  EXPECT_DOUBLE_EQ(s.number("render.exposure"), 1.0);
  s.set_from_text("render.hdr=off", "--set");
  EXPECT_FALSE(s.flag("render.hdr"));
  s.set_from_text("render.antialias=msaa4", "--set");
  s.set_from_text("render.bloom=high", "--set");
  s.set_from_text("render.exposure=0.7", "--set");
  EXPECT_EQ(s.choice("render.antialias"), "msaa4");
  EXPECT_DOUBLE_EQ(s.number("render.exposure"), 0.7);
  for (const char* bad : {"render.hdr=maybe", "render.bloom=ultra", "render.bloom=0.5", "render.antialias=msaa8",
                          "render.antialias=", "render.exposure=0", "render.exposure=-1", "render.exposure=inf",
                          "render.exposure=bright"})
    EXPECT_THROW(s.set_from_text(bad, "--set"), arc::InputError) << bad;
  try {
    s.set_from_text("render.antialias=smaa", "--set");
  } catch (const arc::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("render.antialias"), std::string::npos) << m;
    EXPECT_NE(m.find("msaa4"), std::string::npos) << "names what is allowed: " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
  }
  const std::string listed = s.describe();
  for (const char* key : {"render.hdr", "render.bloom", "render.exposure", "render.antialias"})
    EXPECT_NE(listed.find(key), std::string::npos) << key << " is in --list-settings";
}

TEST(Settings, PresetsSetTheLook) {
  const std::string path = arc::data_root() + "/assets/settings/quality.json";
  auto s = arc::Settings::defaults();
  s.apply_preset_file(path, "low");
  EXPECT_FALSE(s.flag("render.hdr"));
  EXPECT_EQ(s.choice("render.antialias"), "off");
  s.apply_preset_file(path, "reference");
  EXPECT_TRUE(s.flag("render.hdr"));
  EXPECT_EQ(s.choice("render.bloom"), "high");
  EXPECT_EQ(s.choice("render.antialias"), "msaa4");
}
