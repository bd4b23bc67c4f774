// game/render/hud_rules.h — the tunable numbers of the HUD and of the own-effect view rules,
// from assets/settings/hud.json (format in levels/README.md, "HUD settings"); no GL.
//
// HudState (hud_layout.h) carries one; its defaults are the file's documented defaults, so a
// frame built without the file (benchmarks, tests) looks like the shipped game. A bad file
// throws InputError with `path:line:col: what is wrong and what is allowed`.
//
// Example, compiled as HudRules.BannerExample in tests/unit/game/test_hud.cpp:
//   HudState hud;
//   hud.rules = load_hud_rules("assets/settings/hud.json");
#pragma once
#include <string>

#include "game/render/own_view.h"

namespace arc {

struct HudRules {
  OwnViewRules own_view;
  double radar_min_range = 500;        // m: the radar never zooms in closer than this
  double radar_max_range = 8000;       // m: nor out farther
  double radar_margin = 1.3;           // its range is the nearest threats' distance times this
  int radar_threats = 2;               // how many of the nearest hostiles and missiles it fits
  double hit_marker_seconds = 0.25;    // a hit by the player's weapons marks the crosshair this long
  double damage_seconds = 1.5;         // a hit on the player shows its direction this long
  double kill_feed_seconds = 8;        // a kill stays in the feed this long
  int kill_feed_lines = 4;             // at most this many kills in the feed
};

HudRules load_hud_rules(const std::string& path);

}  // namespace arc
