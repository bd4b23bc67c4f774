// The settings mechanism (core/settings.h) on keys defined here; the game's own keys and the
// shipped presets are tested with the assembled set in tests/unit/app/test_all_settings.cpp.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/error.h"
#include "core/settings.h"
#include "core/data_root.h"

namespace {

// One key of each kind, as a module registers them.
arc::Settings sample() {
  arc::Settings s;
  s.define_number("render.scale", 1.0, 0.25, 2.0, "render resolution relative to the window");
  s.define_choice("render.sorting", "full", {"off", "cluster", "full"}, "particle order");
  s.define_flag("render.hdr", false, "float scene");
  s.define_integer("particles.budget", 200000, 1000, 4000000, "largest number of live particles");
  return s;
}

const char* kPresets = R"({
  "presets": {
    "low": { "render.scale": 0.5, "render.sorting": "off", "render.hdr": false, "particles.budget": 50000 },
    "bad": { "render.scale": 9 },
    "unknown": { "render.fuzz": 1 }
  }
})";

}  // namespace

using arc::Settings;

TEST(SettingsExample, DefineSetAndRead) {
  Settings s;
  s.define_choice("render.sorting", "full", {"off", "cluster", "full"}, "particle order; cheap");
  s.set_from_text("render.sorting=cluster", "--set");
  std::string m = s.choice("render.sorting");
  EXPECT_EQ(m, "cluster");
}

TEST(Settings, DefaultsAreListedInDefinitionOrder) {
  const arc::Settings s = sample();
  EXPECT_EQ(s.choice("render.sorting"), "full");
  EXPECT_EQ(s.integer("particles.budget"), 200000);
  EXPECT_EQ(s.describe(),
            "  render.scale = 1  (a number in [0.25, 2])  render resolution relative to the window\n"
            "  render.sorting = full  (one of off, cluster or full)  particle order\n"
            "  render.hdr = false  (true or false (or on/off, 1/0))  float scene\n"
            "  particles.budget = 200000  (an integer in [1000, 4e+06])  largest number of live particles\n");
}

TEST(Settings, AKeyIsDefinedOnce) {
  arc::Settings s = sample();
  EXPECT_THROW(s.define_flag("render.hdr", true, "again"), std::logic_error);
  EXPECT_EQ(s.all().size(), 4u);
}

TEST(Settings, SetChecksKeyTypeAndRange) {
  arc::Settings s = sample();
  s.set_from_text("render.scale=0.5", "--set");
  EXPECT_DOUBLE_EQ(s.number("render.scale"), 0.5);
  EXPECT_THROW(s.set_from_text("render.scale=9", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.scale=nan", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.sorting=random", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("no.such=1", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.scale", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("particles.budget=1.5", "--set"), arc::InputError);
  EXPECT_THROW(s.set_from_text("render.hdr=maybe", "--set"), arc::InputError);
  s.set_from_text("render.hdr=on", "--set");
  EXPECT_TRUE(s.flag("render.hdr"));
  try {
    s.set_from_text("render.sorting=some", "--set render.sorting=some");
    ADD_FAILURE() << "no error";
  } catch (const arc::InputError& e) {
    EXPECT_STREQ(e.what(), "--set render.sorting=some: setting 'render.sorting' must be one of off, cluster or full, "
                           "got 'some'");
  }
}

// An integer written with a zero fraction (as JSON writers put 50000) is that integer, in a
// preset as on the command line; a non-zero fraction, hex and infinities are refused.
TEST(Settings, IntegersWrittenWithAZeroFractionAreAccepted) {
  arc::Settings s = sample();
  s.set_from_text("particles.budget=50000.0", "--set");
  EXPECT_EQ(s.integer("particles.budget"), 50000);
  s.set_from_text("particles.budget=6e4", "--set");
  EXPECT_EQ(s.integer("particles.budget"), 60000);
  for (const char* bad : {"particles.budget=50000.5", "particles.budget=0x1000", "particles.budget=inf",
                          "particles.budget=5e6", "particles.budget="})
    EXPECT_THROW(s.set_from_text(bad, "--set"), arc::InputError) << bad;
  s.apply_preset_text(R"({ "presets": { "p": { "particles.budget": 70000.0 } } })", "q.json", "p");
  EXPECT_EQ(s.integer("particles.budget"), 70000);
}

TEST(Settings, PresetsApplyOrNameTheirFault) {
  arc::Settings s = sample();
  EXPECT_EQ(arc::Settings::preset_names_text(kPresets, "q.json").size(), 3u);
  s.apply_preset_text(kPresets, "q.json", "low");
  EXPECT_DOUBLE_EQ(s.number("render.scale"), 0.5);
  EXPECT_EQ(s.choice("render.sorting"), "off");
  EXPECT_EQ(s.integer("particles.budget"), 50000);
  EXPECT_THROW(s.apply_preset_text(kPresets, "q.json", "ultra"), arc::InputError);
  EXPECT_THROW(s.apply_preset_text(kPresets, "q.json", "bad"), arc::InputError);
  try {
    s.apply_preset_text(kPresets, "q.json", "unknown");
    ADD_FAILURE() << "no error";
  } catch (const arc::InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("q.json:5:18: unknown setting 'render.fuzz'", 0), 0u) << m;
  }
}
