// The session recorder: a live Game's input, commands and periodic hashes as a replay script.
#include "game/app/session_recorder.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/json.h"
#include "game/app/script_feeder.h"
#include "game/sim/world.h"

namespace arc {

SessionRecorder::SessionRecorder(const std::string& path, const std::string& level_path, const Game& game,
                                 const std::string& build_id)
    : path_(path) {
  const World& w = game.world();
  replay::Header h;
  h.level = level_path;
  h.seed = w.seed;
  tick_rate_ = static_cast<uint64_t>(std::lround(1.0 / w.dt));
  h.tick_rate = static_cast<int>(tick_rate_);
  h.difficulty = difficulty_name(static_cast<Difficulty>(w.difficulty));
  h.build = build_id;
  // The settings that change the simulation travel with the recording, so a session played
  // with --quality low replays exactly under any other quality.
  h.particle_budget = w.options.particle_budget;
  h.lightning_interval = w.options.lightning_interval;
  h.substeps = w.options.substeps;
  // The cull distance decides which clusters skip ticks, and that is in the hash.
  if (w.options.cull_distance != GameOptions{}.cull_distance) {
    std::ostringstream d;
    d << w.options.cull_distance;
    h.settings.push_back({"particles.cull_distance", d.str()});
  }
  // The header lands complete or not at all; lines are then appended to the renamed file.
  write_file_atomic(path, replay::header_text(h) + "# recorded live session\n");
  file_ = std::fopen(path.c_str(), "ab");
  if (!file_) throw InputError("--record " + path + ": cannot open for appending");
  last_tick_ = w.steps;
}

SessionRecorder::~SessionRecorder() {
  if (finished_ || !file_) return;
  write(replay::end_line(last_tick_));
  std::fclose(file_);
}

void SessionRecorder::write(const std::string& text) {
  if (text.empty() || !file_) return;
  std::fwrite(text.data(), 1, text.size(), file_);
  std::fflush(file_);
}

void SessionRecorder::record(const Game& game, const InputFrame& input, const std::vector<Command>& commands) {
  if (finished_) return;
  // Script ticks count step() calls: paused steps do not advance game time but do count.
  const uint64_t t = game.world().steps;
  std::string lines;
  if (t % tick_rate_ == 0 && t > 0) {
    replay::HashCheck h;
    h.tick = t;
    h.value = game.hash();
    lines += replay::hash_line(h);
  }
  const replay::InputState now = to_input_state(input);
  lines += replay::input_diff_lines(t, held_, now);
  held_ = now;
  for (Command c : commands) {
    if (c == Command::None) continue;
    replay::CommandEvent e;
    e.tick = t;
    e.command = static_cast<replay::ScriptCommand>(c);
    lines += replay::command_line(e);
  }
  write(lines);
  last_tick_ = t + 1;
}

void SessionRecorder::finish(const Game& game) {
  if (finished_ || !file_) return;
  replay::HashCheck h;
  h.tick = game.world().steps;
  h.value = game.hash();
  write(replay::hash_line(h) + replay::end_line(h.tick));
  std::fclose(file_);
  file_ = nullptr;
  finished_ = true;
}

}  // namespace arc
