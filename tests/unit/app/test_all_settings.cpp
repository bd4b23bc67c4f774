// The game's settings as the app assembles them (game/app/all_settings.h): each module's keys
// under its own prefix, and the shipped quality presets valid against the whole set.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/data_root.h"
#include "audio/audio_settings.h"
#include "core/error.h"
#include "game/app/all_settings.h"
#include "game/net/net_settings.h"
#include "game/sim/sim_settings.h"
#include "gfx/render_settings.h"
#include "particles/particle_settings.h"

namespace arc {
namespace {

const std::string kQuality = arc::data_root() + "/assets/settings/quality.json";

std::vector<std::string> keys_of(void (*register_keys)(Settings&)) {
  Settings s;
  register_keys(s);
  std::vector<std::string> keys;
  for (const SettingDef& d : s.all()) keys.push_back(d.key);
  return keys;
}

TEST(AllSettings, PresetOverDefaults) {
  Settings s = all_settings();
  s.apply_preset_file(arc::data_root() + "/assets/settings/quality.json", "high");
  s.set_from_text("render.sorting=full", "--set");
  std::string m = s.choice("render.soft_edges");
  EXPECT_EQ(m, "effect");
  EXPECT_TRUE(s.flag("render.hdr"));
}

TEST(AllSettings, EachModuleRegistersItsOwnKeys) {
  const struct {
    void (*register_keys)(Settings&);
    std::string prefix;
    size_t count;
  } modules[] = {{register_render_settings, "render.", 22},
                 {register_particle_settings, "particles.", 3},
                 {register_sim_settings, "sim.", 3},
                 {register_net_settings, "net.", 5},
                 {register_audio_settings, "audio.", 11}};
  std::vector<std::string> assembled;
  for (const auto& m : modules) {
    const std::vector<std::string> keys = keys_of(m.register_keys);
    EXPECT_EQ(keys.size(), m.count) << m.prefix;
    for (const std::string& k : keys) EXPECT_EQ(k.rfind(m.prefix, 0), 0u) << k << " is not a " << m.prefix << " key";
    assembled.insert(assembled.end(), keys.begin(), keys.end());
  }
  const Settings settings = all_settings();
  std::vector<std::string> all;
  for (const SettingDef& d : settings.all()) all.push_back(d.key);
  EXPECT_EQ(all, assembled) << "all_settings() is the modules' keys in this order";
}

TEST(AllSettings, DefaultsAreDocumentedAndValid) {
  const Settings s = all_settings();
  EXPECT_EQ(s.choice("render.sorting"), "full");
  EXPECT_EQ(s.integer("particles.budget"), 400000);
  EXPECT_DOUBLE_EQ(s.number("render.target_frame_ms"), 16.7);
  for (const SettingDef& d : s.all()) {
    EXPECT_FALSE(d.doc.empty()) << d.key;
    Settings again = s;
    EXPECT_NO_THROW(again.set(d.key, d.value, "default")) << d.key << " = " << d.value;
  }
}

TEST(AllSettings, EveryShippedPresetApplies) {
  auto names = Settings::preset_names(kQuality);
  ASSERT_EQ(names.size(), 4u);
  for (const auto& n : names) {
    Settings s = all_settings();
    EXPECT_NO_THROW(s.apply_preset_file(kQuality, n)) << n;
  }
  Settings s = all_settings();
  s.apply_preset_file(kQuality, "low");
  EXPECT_EQ(s.choice("render.soft_edges"), "off");
  EXPECT_THROW(s.apply_preset_file(kQuality, "ultra"), InputError);
}

TEST(AllSettings, HdrBloomExposureAndAntialiasAreValidated) {
  Settings s = all_settings();
  // The default is the 8-bit scene: the look's passes are costly on a software rasteriser.
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
    EXPECT_THROW(s.set_from_text(bad, "--set"), InputError) << bad;
  try {
    s.set_from_text("render.antialias=smaa", "--set");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("render.antialias"), std::string::npos) << m;
    EXPECT_NE(m.find("msaa4"), std::string::npos) << "names what is allowed: " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
  }
  const std::string listed = s.describe();
  for (const char* key : {"render.hdr", "render.bloom", "render.exposure", "render.antialias"})
    EXPECT_NE(listed.find(key), std::string::npos) << key << " is in --list-settings";
}

TEST(AllSettings, PresetsSetTheLook) {
  Settings s = all_settings();
  s.apply_preset_file(kQuality, "low");
  EXPECT_FALSE(s.flag("render.hdr"));
  EXPECT_EQ(s.choice("render.antialias"), "off");
  s.apply_preset_file(kQuality, "reference");
  EXPECT_TRUE(s.flag("render.hdr"));
  EXPECT_EQ(s.choice("render.bloom"), "high");
  EXPECT_EQ(s.choice("render.antialias"), "msaa4");
}

}  // namespace
}  // namespace arc

namespace arc {
TEST(AllSettings, TargetFrameTimeValidatesItsRange) {
  Settings s = all_settings();
  EXPECT_NO_THROW(s.set("render.target_frame_ms", "0", "--set"));  // off
  EXPECT_NO_THROW(s.set("render.target_frame_ms", "33.3", "--set"));
  for (const char* bad : {"-1", "1001", "fast", "nan"}) {
    try {
      s.set("render.target_frame_ms", bad, "--set");
      ADD_FAILURE() << bad << " was taken";
    } catch (const std::exception& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("render.target_frame_ms"), std::string::npos) << what;
      EXPECT_NE(what.find("[0, 1000]"), std::string::npos) << what;
    }
  }
}
}  // namespace arc
