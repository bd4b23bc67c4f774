// The game's sound per tick in the arena battle: reading the tick's sound events from the
// World, cueing them, advancing fades and mixing one tick of samples through OpenAL Soft's
// loopback device (48 kHz stereo, 800 frames a tick). The simulation's own time is not counted.
#include <algorithm>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/audio_session.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "core/data_root.h"

namespace arc {
namespace {

ARCFIRE_SCENE(audio_arena) {
  GameOptions options;
  options.root_dir = arc::data_root();
  Game game = Game::load_level(arc::data_root() + "/levels/arena.json", options);
  AudioSession audio(arc::data_root() + "/assets/sounds/sounds.json", all_settings(), true);
  if (!audio.engine().active()) return;
  std::vector<float> block(800 * 2);
  std::vector<double> ms;
  int voices_max = 0;
  size_t events_max = 0;
  for (int t = 0; t < 3600 && game.world().outcome == Outcome::Undecided; ++t) {
    game.step(InputFrame{});
    const double start = bench::now_seconds();
    audio.after_tick(game.world());
    audio.frame(game.world(), game.world().dt);
    audio.engine().render(block.data(), 800);
    ms.push_back((bench::now_seconds() - start) * 1e3);
    voices_max = std::max(voices_max, audio.engine().voice_count());
    events_max = std::max(events_max, audio.last_events().size());
  }
  double sum = 0;
  for (double m : ms) sum += m;
  bench::report_metric("audio_ms_per_tick", ms.empty() ? 0.0 : sum / double(ms.size()));
  bench::report_metric("audio_ms_per_tick_median", bench::median(ms));
  bench::report_metric("audio_voices_max_arena", voices_max);
  bench::report_metric("audio_events_max_arena", double(events_max));
  bench::report_metric("audio_ticks_arena", double(ms.size()));
}

}  // namespace
}  // namespace arc
