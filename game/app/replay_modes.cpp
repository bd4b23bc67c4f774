#include "game/app/replay_modes.h"

#include "game/app/replay_cli.h"

namespace arc {

int run_replay_from_options(const AppOptions& o) {
  ReplayRunOptions r;
  r.script_path = o.replay_path;
  r.out_dir = o.out_dir;
  r.update_golden = o.update_golden;
  r.no_render = o.no_render;
  r.game = o.game;
  r.settings = o.settings;
  return run_replay(r);
}

int run_serialization_test_from_options(const AppOptions& o) {
  SerializationTestOptions s;
  s.level_path = o.level;
  s.game = o.game;
  s.every = o.serialization_test;
  if (o.ticks > 0) s.ticks = o.ticks;
  return run_serialization_test(s);
}

}  // namespace arc
