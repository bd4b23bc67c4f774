#include "game/app/replay_cli.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/json.h"
#include "game/app/frame_renderer.h"
#include "game/sim/world.h"
#include "gfx/image_compare.h"
#include "replay/hash_log.h"

namespace arc {

// The script's names for inputs and commands are the game's, value for value.
static_assert(uint16_t(replay::kFirePrimary) == kFirePrimary && uint16_t(replay::kFireSecondary) == kFireSecondary &&
              uint16_t(replay::kAfterburner) == kAfterburner && uint16_t(replay::kFlightAssist) == kFlightAssist);
static_assert(uint8_t(replay::ScriptCommand::TargetNext) == uint8_t(Command::TargetNext) &&
              uint8_t(replay::ScriptCommand::TargetNearest) == uint8_t(Command::TargetNearest) &&
              uint8_t(replay::ScriptCommand::TargetNextHostile) == uint8_t(Command::TargetNextHostile) &&
              uint8_t(replay::ScriptCommand::SwitchWeapon) == uint8_t(Command::SwitchWeapon) &&
              uint8_t(replay::ScriptCommand::CameraToggle) == uint8_t(Command::CameraToggle) &&
              uint8_t(replay::ScriptCommand::Pause) == uint8_t(Command::Pause) &&
              uint8_t(replay::ScriptCommand::Resume) == uint8_t(Command::Resume));

InputFrame to_input_frame(const replay::InputState& s) {
  InputFrame f;
  f.pitch = s.axes[0];
  f.yaw = s.axes[1];
  f.roll = s.axes[2];
  f.throttle = s.axes[3];
  f.strafe_x = s.axes[4];
  f.strafe_y = s.axes[5];
  f.buttons = s.buttons;
  return f;
}

replay::InputState to_input_state(const InputFrame& f) {
  replay::InputState s;
  s.axes = {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y};
  s.buttons = f.buttons;
  return s;
}

namespace {

namespace fs = std::filesystem;
using replay::Expectation;

const char* difficulty_name(int d) { return d == 0 ? "easy" : d == 2 ? "hard" : "normal"; }

// A level named in a script: as written (relative to the working folder), else relative to
// the game's root folder, so scripts run from any folder.
std::string resolve_level(const replay::Script& s, const std::string& root) {
  const std::string& level = s.header.level;
  if (fs::exists(level)) return level;
  fs::path under_root = fs::path(root) / level;
  if (!fs::path(level).is_absolute() && fs::exists(under_root)) return under_root.string();
  throw InputError(s.path + ":" + std::to_string(s.header.level_line) + ":1: level file '" + level +
                   "' not found (looked in the working folder and in " + root + ")");
}

GameOptions script_game_options(const replay::Script& s, GameOptions o) {
  if (s.header.particle_budget) o.particle_budget = *s.header.particle_budget;
  if (s.header.lightning_interval) o.lightning_interval = *s.header.lightning_interval;
  if (s.header.substeps) o.substeps = *s.header.substeps;
  if (s.header.seed) {
    o.seed_override = true;
    o.seed = *s.header.seed;
  }
  if (s.header.difficulty) {
    o.difficulty_override = true;
    const std::string& d = *s.header.difficulty;
    o.difficulty = d == "easy" ? Difficulty::Easy : d == "hard" ? Difficulty::Hard : Difficulty::Normal;
  }
  return o;
}

const Ship* find_ship(const World& w, const std::string& name) {
  for (const Ship& s : w.ships)
    if (s.name == name) return &s;
  return nullptr;
}

// Names in expectations must exist in the level: a typo is bad input (exit 2), not a failure.
void check_names(const replay::Script& s, const World& w) {
  std::vector<std::string> names;
  for (const Ship& sh : w.ships) names.push_back("'" + sh.name + "'");
  auto require = [&](const Expectation& e, const std::string& name, int col) {
    if (name.empty() || find_ship(w, name)) return;
    throw InputError(s.path + ":" + std::to_string(e.src.line) + ":" + std::to_string(col) + ": no ship named '" + name +
                     "' in level " + w.level.name + "; ships: " + join_allowed(names));
  };
  for (const Expectation& e : s.expectations) {
    require(e, e.ship, e.ship_col);
    require(e, e.other, e.other_col);
  }
  if (s.header.tick_rate && std::lround(1.0 / w.dt) != *s.header.tick_rate)
    throw InputError(s.path + ": header tick_rate " + std::to_string(*s.header.tick_rate) +
                     " differs from the level's " + std::to_string(std::lround(1.0 / w.dt)));
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string trimmed(const std::string& line) {
  size_t b = line.find_first_not_of(" \t");
  size_t e = line.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : line.substr(b, e - b + 1);
}

// The reason an expectation fails, or nullopt when it holds.
std::optional<std::string> evaluate(const Expectation& e, const World& w) {
  const Ship* a = find_ship(w, e.ship);
  switch (e.kind) {
    case Expectation::Kind::Alive:
      if (a->alive) return std::nullopt;
      return e.ship + " was destroyed at tick " + std::to_string(a->death_tick);
    case Expectation::Kind::Destroyed:
      if (!a->alive) return std::nullopt;
      return e.ship + " is alive (hull " + number(a->hull) + ")";
    case Expectation::Kind::Hull:
      if (e.range.contains(a->hull)) return std::nullopt;
      return "hull of " + e.ship + " is " + number(a->hull);
    case Expectation::Kind::Shield:
      if (e.range.contains(a->shield)) return std::nullopt;
      return "shield of " + e.ship + " is " + number(a->shield);
    case Expectation::Kind::Position: {
      const glm::dvec3& p = a->position;
      if (e.box[0].contains(p.x) && e.box[1].contains(p.y) && e.box[2].contains(p.z)) return std::nullopt;
      return e.ship + " is at " + number(p.x) + " " + number(p.y) + " " + number(p.z);
    }
    case Expectation::Kind::Distance: {
      const Ship* b = find_ship(w, e.other);
      double d = glm::length(a->position - b->position);
      if (e.range.contains(d)) return std::nullopt;
      return "distance is " + number(d);
    }
    case Expectation::Kind::Particles: {
      double n = double(w.particles->stats().live_particles);
      if (e.range.contains(n)) return std::nullopt;
      return "particle count is " + number(n);
    }
    case Expectation::Kind::Winner: {
      std::string winner = w.outcome == Outcome::Undecided || w.winner.empty() ? "none" : w.winner;
      if (winner == e.team) return std::nullopt;
      return "winner is " + winner;
    }
  }
  return std::nullopt;
}

void make_dir(const std::string& dir, const std::string& what) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw InputError(what + " " + dir + ": cannot create folder (" + ec.message() + ")");
}

class ProgressBar {
 public:
  ProgressBar(uint64_t total, bool enabled) : total_(total), on_(enabled && total >= 600 && isatty(STDERR_FILENO)) {}
  void update(uint64_t tick) {
    if (!on_) return;
    int pct = int(tick * 100 / total_);
    if (pct == shown_) return;
    shown_ = pct;
    std::fprintf(stderr, "\r[%-40s] %3d%% tick %llu/%llu", std::string(size_t(pct * 40 / 100), '#').c_str(), pct,
                 static_cast<unsigned long long>(tick), static_cast<unsigned long long>(total_));
  }
  ~ProgressBar() {
    if (on_) std::fprintf(stderr, "\r%70s\r", "");
  }

 private:
  uint64_t total_;
  bool on_;
  int shown_ = -1;
};

// Feeds a script's held input and commands to a Game, one step at a time.
struct ScriptFeeder {
  explicit ScriptFeeder(const replay::Script& s) : script(&s) {}
  const replay::Script* script;
  size_t next_input = 0, next_command = 0;
  replay::InputState held;

  void step(Game& game, uint64_t t) {
    for (; next_input < script->inputs.size() && script->inputs[next_input].tick == t; ++next_input)
      replay::apply_input(held, script->inputs[next_input]);
    std::vector<Command> commands;
    for (; next_command < script->commands.size() && script->commands[next_command].tick == t; ++next_command)
      commands.push_back(static_cast<Command>(script->commands[next_command].command));
    game.step(to_input_frame(held), commands);
  }
};

struct Player {
  const ReplayRunOptions& opt;
  replay::Script script;
  std::string level_path;
  GameOptions game_options;
  Game game;
  std::unique_ptr<FrameRenderer> renderer;
  std::string golden_dir, out_dir;
  std::optional<replay::HashLog> golden_log;
  replay::HashLog log;
  std::vector<uint64_t> hash_values;  // per script hash line, for --update-golden
  ReplayOutcome result;
  bool divergence_reported = false;
  uint64_t last_matching_hash_tick = 0;
  size_t next_full = 0;          // golden_log->full entries before this one are behind us
  uint64_t last_full_match = 0;  // the last tick whose full hash matched the log

  void fail(uint64_t tick, const replay::SourceLine& src, const std::string& why) {
    ++result.failures;
    std::printf("FAIL %s:%d: tick %llu: %s: %s\n", script.path.c_str(), src.line, static_cast<unsigned long long>(tick),
                trimmed(src.text).c_str(), why.c_str());
  }
  void pass(uint64_t tick, const replay::SourceLine& src) {
    if (!opt.quiet)
      std::printf("ok   %s:%d: tick %llu: %s\n", script.path.c_str(), src.line, static_cast<unsigned long long>(tick),
                  trimmed(src.text).c_str());
  }
  std::string log_path() const { return (fs::path(golden_dir) / "hashes.txt").string(); }

  // The cheap hash is compared with the golden log on every tick the log covers, so its first
  // mismatch is the first diverging tick (check_log reports it on the spot). Other mismatches
  // (a script's hash line, a full hash) come here: a second run from tick 0 hashes every tick
  // up to it to find the first one that diverged, and dumps the state there.
  void report_divergence(uint64_t mismatch_tick) {
    if (divergence_reported) return;
    divergence_reported = true;
    if (!golden_log) {
      std::printf("  no golden hash log (%s): the first diverging tick is after tick %llu; state at tick %llu:\n%s",
                  log_path().c_str(), static_cast<unsigned long long>(last_matching_hash_tick),
                  static_cast<unsigned long long>(mismatch_tick), game.state_dump().c_str());
      return;
    }
    Game again = Game::load_level(level_path, game_options);
    ScriptFeeder feed(script);
    for (uint64_t t = 0; t <= mismatch_tick && t < golden_log->hashes.size(); ++t) {
      const uint64_t h = again.hash();
      if (h != golden_log->hashes[t]) {
        std::printf("  first diverging tick %llu: state hash %s, golden log %s says %s; state at tick %llu:\n%s",
                    static_cast<unsigned long long>(t), replay::hex64(h).c_str(), log_path().c_str(),
                    replay::hex64(golden_log->hashes[t]).c_str(), static_cast<unsigned long long>(t),
                    again.state_dump().c_str());
        return;
      }
      feed.step(again, t);
    }
    std::printf("  every tick up to %llu matches the golden log's cheap hash; the full state (particles) diverged "
                "first; state at tick %llu:\n%s",
                static_cast<unsigned long long>(mismatch_tick), static_cast<unsigned long long>(mismatch_tick),
                game.state_dump().c_str());
  }

  // Every tick: the cheap hash against the log's entry for the tick; with `full` (checkpoint
  // ticks), the full hash against the log's full entry when it has one for the tick.
  void check_log(uint64_t t, uint64_t cheap, std::optional<uint64_t> full) {
    if (!golden_log || divergence_reported || t >= golden_log->hashes.size()) return;
    const auto& fulls = golden_log->full;
    while (next_full < fulls.size() && fulls[next_full].first < t) ++next_full;
    std::optional<uint64_t> want_full;
    if (full && next_full < fulls.size() && fulls[next_full].first == t) want_full = fulls[next_full].second;
    const bool cheap_ok = golden_log->hashes[t] == cheap;
    if (cheap_ok && (!want_full || *want_full == *full)) {
      if (want_full) last_full_match = t;
      return;
    }
    ++result.failures;
    divergence_reported = true;
    if (!cheap_ok) {
      // Every earlier tick matched, so this is the first one that diverged.
      std::printf("FAIL %s: tick %llu: state differs from the golden hash log %s\n"
                  "  first diverging tick %llu: state hash %s, golden log says %s; state at tick %llu:\n%s",
                  script.path.c_str(), static_cast<unsigned long long>(t), log_path().c_str(),
                  static_cast<unsigned long long>(t), replay::hex64(cheap).c_str(),
                  replay::hex64(golden_log->hashes[t]).c_str(), static_cast<unsigned long long>(t),
                  game.state_dump().c_str());
      return;
    }
    std::printf("FAIL %s: tick %llu: full state hash %s, golden log %s says %s\n"
                "  the cheap hash matched every tick up to %llu; the full state (every particle) diverged after the "
                "last matching full hash at tick %llu; state at tick %llu:\n%s",
                script.path.c_str(), static_cast<unsigned long long>(t), replay::hex64(*full).c_str(),
                log_path().c_str(), replay::hex64(*want_full).c_str(), static_cast<unsigned long long>(t),
                static_cast<unsigned long long>(last_full_match), static_cast<unsigned long long>(t),
                game.state_dump().c_str());
  }

  void check_hash(size_t i, uint64_t t, uint64_t cheap, uint64_t full) {
    const replay::HashCheck& c = script.hashes[i];
    uint64_t actual = c.full ? full : cheap;
    hash_values[i] = actual;
    ++result.checks;
    if (opt.update_golden) return;
    if (!c.value) {
      fail(t, c.src, "hash not filled in yet; run with --update-golden to record " + replay::hex64(actual));
      return;
    }
    if (*c.value == actual) {
      last_matching_hash_tick = t;
      pass(t, c.src);
      return;
    }
    fail(t, c.src, "hash is " + replay::hex64(actual));
    report_divergence(t);
  }

  void check_snapshot(const replay::SnapshotCheck& s, uint64_t t) {
    ++result.checks;
    if (!renderer) return;
    Image actual = renderer->render(game);
    ++result.frames_rendered;
    std::string golden = (fs::path(golden_dir) / (s.name + ".png")).string();
    make_dir(out_dir, "--out");
    save_image((fs::path(out_dir) / (s.name + ".png")).string(), actual);
    if (opt.update_golden) {
      make_dir(golden_dir, "golden folder");
      save_image(golden, actual);
      if (!opt.quiet) std::printf("updated %s\n", golden.c_str());
      return;
    }
    if (!fs::exists(golden)) {
      fail(t, s.src, "no golden image " + golden + "; run with --update-golden after checking " +
                         (fs::path(out_dir) / (s.name + ".png")).string());
      return;
    }
    Image expected = load_image(golden);
    ImageDiff d = compare_images(expected, actual);
    if (d.passed) {
      pass(t, s.src);
      return;
    }
    std::string prefix = (fs::path(out_dir) / s.name).string();
    write_failure_images(prefix, actual, expected);
    fail(t, s.src, d.summary() + "; wrote " + prefix + "_actual.png and " + prefix + "_diff.png");
  }

  void run() {
    const uint64_t last = script.last_tick();
    const uint64_t every = uint64_t(std::max(opt.full_hash_every, 1));
    size_t ei = 0, hi = 0, si = 0;
    ScriptFeeder feed(script);
    ProgressBar bar(last, !opt.quiet);
    for (uint64_t t = 0;; ++t) {
      const bool hash_line = hi < script.hashes.size() && script.hashes[hi].tick == t;
      const bool checkpoint = t % every == 0 || t == last;
      // The cheap hash runs every tick (a small part of a step); the full hash, which visits
      // every particle, only at checkpoints and hash lines.
      if (opt.update_golden || hash_line || golden_log) {
        const uint64_t cheap = game.hash();
        const bool want_full = hash_line || (checkpoint && (opt.update_golden || golden_log));
        const uint64_t full = want_full ? game.full_hash() : 0;
        if (opt.update_golden) {
          log.hashes.push_back(cheap);
          if (t % every == 0) log.full.emplace_back(t, full);
        } else {
          check_log(t, cheap, want_full ? std::optional<uint64_t>(full) : std::nullopt);
        }
        for (; hi < script.hashes.size() && script.hashes[hi].tick == t; ++hi) check_hash(hi, t, cheap, full);
      }
      for (; ei < script.expectations.size() && script.expectations[ei].tick == t; ++ei) {
        const Expectation& e = script.expectations[ei];
        ++result.checks;
        if (auto why = evaluate(e, game.world())) fail(t, e.src, *why);
        else pass(t, e.src);
      }
      for (; si < script.snapshots.size() && script.snapshots[si].tick == t; ++si) check_snapshot(script.snapshots[si], t);
      if (t >= last) break;
      feed.step(game, t);
      if (renderer && opt.render_every > 0 && (t + 1) % uint64_t(opt.render_every) == 0) {
        renderer->render(game);
        ++result.frames_rendered;
      }
      bar.update(t + 1);
    }
    result.ticks = last;
    result.final_hash = game.hash();
  }

  void update_golden(const std::string& original_text) {
    make_dir(golden_dir, "golden folder");
    write_file_atomic(log_path(), replay::write_hash_log(log));
    std::string filled = replay::fill_hash_values(original_text, script, hash_values);
    if (filled != original_text) write_file_atomic(script.path, filled);
    std::printf("updated %zu hash lines in %s and the hash log %s\n", script.hashes.size(), script.path.c_str(),
                log_path().c_str());
  }
};

}  // namespace

ReplayOutcome play_replay(const ReplayRunOptions& opt) {
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  const std::string text = read_text_file(opt.script_path);
  replay::Script script = replay::parse_script(text, opt.script_path);
  const std::string level_path = resolve_level(script, opt.game.root_dir == "." ? ARCFIRE_SOURCE_DIR : opt.game.root_dir);
  GameOptions game_options = script_game_options(script, opt.game);
  Player p{opt,    script, level_path, game_options, Game::load_level(level_path, game_options), nullptr, "", "",
           std::nullopt, {}, {}, {}};
  check_names(p.script, p.game.world());
  const std::string stem = fs::path(opt.script_path).stem().string();
  p.golden_dir = !opt.golden_dir.empty() ? opt.golden_dir
                                         : (fs::path(opt.script_path).parent_path() / "golden" / stem).string();
  p.out_dir = !opt.out_dir.empty() ? opt.out_dir : (fs::path("out") / "replay" / stem).string();
  p.hash_values.assign(p.script.hashes.size(), 0);
  const std::string log_path = (fs::path(p.golden_dir) / "hashes.txt").string();
  if (!opt.update_golden && fs::exists(log_path)) p.golden_log = replay::parse_hash_log(read_text_file(log_path), log_path);
  // Only a frame to look at makes a GL context: replays without snapshots never create one.
  if (!opt.no_render && (!p.script.snapshots.empty() || opt.render_every > 0)) {
    FrameRendererDesc desc;
    desc.width = p.script.header.snapshot_width;
    desc.height = p.script.header.snapshot_height;
    p.renderer = std::make_unique<FrameRenderer>(desc, opt.settings, p.game);
  }
  const clock::time_point ready = clock::now();
  p.run();
  p.result.setup_seconds = std::chrono::duration<double>(ready - start).count();
  p.result.run_seconds = std::chrono::duration<double>(clock::now() - ready).count();
  if (opt.update_golden) p.update_golden(text);
  if (!opt.quiet || p.result.failures > 0)
    std::printf("%s: %d checks, %d failed%s\n", opt.script_path.c_str(), p.result.checks, p.result.failures,
                opt.no_render && !p.script.snapshots.empty() ? " (snapshots skipped: --no-render)" : "");
  p.result.exit_code = p.result.failures > 0 ? kExitCheckFailed : kExitOk;
  return p.result;
}

int run_replay(const ReplayRunOptions& options) {
  ReplayOutcome r = play_replay(options);
  std::printf("final hash %s at tick %llu\n", replay::hex64(r.final_hash).c_str(),
              static_cast<unsigned long long>(r.ticks));
  std::fflush(stdout);
  return r.exit_code;
}

// ---------------------------------------------------------------- serialization test

int run_serialization_test(const SerializationTestOptions& opt) {
  if (opt.every < 1) throw InputError("--serialization-test: N must be at least 1, got " + std::to_string(opt.every));
  std::optional<replay::Script> script;
  std::string level = opt.level_path;
  GameOptions game_options = opt.game;
  uint64_t last = static_cast<uint64_t>(opt.ticks);
  if (!opt.script_path.empty()) {
    script = replay::load_script(opt.script_path);
    level = resolve_level(*script, opt.game.root_dir == "." ? ARCFIRE_SOURCE_DIR : opt.game.root_dir);
    game_options = script_game_options(*script, opt.game);
    last = script->last_tick();
  }
  Game original = Game::load_level(level, game_options);
  std::optional<Game> restored;
  uint64_t restored_at = 0;
  const replay::Script no_script;
  ScriptFeeder feed_original(script ? *script : no_script), feed_restored = feed_original;
  auto diverged = [&](uint64_t t, const char* which, uint64_t a, uint64_t b) {
    std::printf("FAIL serialization test: first diverging tick %llu (restored from a save at tick %llu): %s %s, "
                "restored %s\n",
                static_cast<unsigned long long>(t), static_cast<unsigned long long>(restored_at), which,
                replay::hex64(a).c_str(), replay::hex64(b).c_str());
    std::printf("original at tick %llu:\n%srestored at tick %llu:\n%s", static_cast<unsigned long long>(t),
                original.state_dump().c_str(), static_cast<unsigned long long>(t), restored->state_dump().c_str());
    return kExitCheckFailed;
  };
  int saves = 0;
  for (uint64_t t = 0;; ++t) {
    if (t > 0 && t % uint64_t(opt.every) == 0) {
      restored = Game::restore(original.save(), level, game_options);
      feed_restored = feed_original;
      restored_at = t;
      ++saves;
    }
    if (restored) {
      if (original.hash() != restored->hash()) return diverged(t, "hash", original.hash(), restored->hash());
      if (t == restored_at || t % uint64_t(opt.every) == uint64_t(opt.every) - 1 || t == last)
        if (original.full_hash() != restored->full_hash())
          return diverged(t, "full hash", original.full_hash(), restored->full_hash());
    }
    if (t >= last) break;
    feed_original.step(original, t);
    if (restored) feed_restored.step(*restored, t);
  }
  std::printf("serialization test: %d save/restore cycles, every %lld ticks, hashes equal on every tick\n", saves,
              static_cast<long long>(opt.every));
  std::printf("final hash %s at tick %llu\n", replay::hex64(original.hash()).c_str(),
              static_cast<unsigned long long>(last));
  return kExitOk;
}

// ---------------------------------------------------------------- recorder

SessionRecorder::SessionRecorder(const std::string& path, const std::string& level_path, const Game& game,
                                 const std::string& build_id)
    : path_(path) {
  const World& w = game.world();
  replay::Header h;
  h.level = level_path;
  h.seed = w.seed;
  tick_rate_ = static_cast<uint64_t>(std::lround(1.0 / w.dt));
  h.tick_rate = static_cast<int>(tick_rate_);
  h.difficulty = difficulty_name(w.difficulty);
  h.build = build_id;
  // The settings that change the simulation travel with the recording, so a session played
  // with --quality low replays exactly under any other quality.
  h.particle_budget = w.options.particle_budget;
  h.lightning_interval = w.options.lightning_interval;
  h.substeps = w.options.substeps;
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
