// Replay speed: the AI duel script (tests/replays/ai_duel_normal.replay) replayed headless,
// as multiples of real time (simulated seconds per wall-clock second of the ticks; loading
// the level and, with rendering, creating the GL context and loading assets are excluded and
// printed separately).
//   replay_speed_norender  the whole duel, simulation and checks only (target >= 100x)
//   replay_speed_render    its first 10 s, rendering every tick at 640x360 through EGL (>= 1x)
// Plus a Google Benchmark of parsing a long recorded script.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "bench_registry.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/app/all_settings.h"
#include "game/app/replay_player.h"
#include "replay/script.h"
#include "core/data_root.h"

namespace {

const std::string kDuel = arc::build_source_tree() + "/tests/replays/ai_duel_normal.replay";

double speed(const arc::ReplayRunOptions& o, arc::ReplayOutcome* outcome) {
  *outcome = arc::play_replay(o);
  return double(outcome->ticks) / 60.0 / outcome->run_seconds;
}

arc::ReplayRunOptions options(const std::string& script) {
  arc::ReplayRunOptions o;
  o.script_path = script;
  o.quiet = true;
  o.game.root_dir = arc::data_root();
  o.out_dir = (std::filesystem::temp_directory_path() / "arcfire-bench-replay").string();
  return o;
}

// A recorded-looking script: an input change on most ticks for ten minutes of play.
std::string long_script() {
  arc::replay::Header h;
  h.level = "levels/duel.json";
  std::string text = arc::replay::header_text(h);
  arc::replay::InputState prev, now;
  for (uint64_t t = 0; t < 36000; ++t) {
    now.axes[t % 6] = static_cast<int8_t>((t * 37) % 255 - 127);
    now.buttons = static_cast<uint16_t>((t / 50) % 16);
    text += arc::replay::input_diff_lines(t, prev, now);
    prev = now;
    if (t % 60 == 0) text += std::to_string(t) + " hash 0123456789abcdef\n";
  }
  return text + arc::replay::end_line(36000);
}

void BM_ParseRecordedScript(benchmark::State& state) {
  const std::string text = long_script();
  const arc::Settings known = arc::all_settings();
  for (auto _ : state) benchmark::DoNotOptimize(arc::replay::parse_script(text, "bench.replay", known));
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(text.size()));
}
BENCHMARK(BM_ParseRecordedScript)->Unit(benchmark::kMillisecond);

}  // namespace

ARCFIRE_SCENE(replay_duel) {
  arc::ReplayOutcome r;
  arc::ReplayRunOptions o = options(kDuel);
  o.no_render = true;
  const double norender = speed(o, &r);
  std::printf("  duel without rendering: %llu ticks in %.3f s (+%.3f s setup), %d checks, %d failed, %.1fx real time\n",
              static_cast<unsigned long long>(r.ticks), r.run_seconds, r.setup_seconds, r.checks, r.failures, norender);
  arc::bench::report_metric("replay_speed_norender", norender);

  // Rendering every tick: the first ten seconds of the same duel (the script cut at tick 600).
  arc::replay::Script s = arc::replay::load_script(kDuel, arc::all_settings());
  s.end_tick = 600;
  s.hashes.clear();
  s.expectations.clear();
  const std::string cut = (std::filesystem::temp_directory_path() / "arcfire-bench-duel-600.replay").string();
  arc::write_file_atomic(cut, arc::replay::write_script(s));
  o = options(cut);
  o.render_every = 1;
  const double render = speed(o, &r);
  std::printf("  duel rendering every tick at %dx%d: %llu ticks, %d frames in %.2f s (+%.2f s setup), %.2fx real time\n",
              s.header.snapshot_width, s.header.snapshot_height, static_cast<unsigned long long>(r.ticks),
              r.frames_rendered, r.run_seconds, r.setup_seconds, render);
  arc::bench::report_metric("replay_speed_render", render);
}
