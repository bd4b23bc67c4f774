// The replay player: steps a Game with a script and checks hashes, the golden hash log,
// expectations and snapshots tick by tick.
#include "game/app/replay_player.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/file_writer.h"
#include "core/input_file.h"
#include "core/input_limits.h"
#include "core/json.h"
#include "game/app/all_settings.h"
#include "game/app/audio_session.h"
#include "game/app/frame_renderer.h"
#include "game/app/replay_expectations.h"
#include "game/app/run_files.h"
#include "game/app/script_feeder.h"
#include "gfx/image_compare.h"
#include "platform/stop_request.h"
#include "replay/hash_log.h"
#include "replay/script.h"

namespace arc {

ReplayRunOptions::ReplayRunOptions(const AppOptions& app)
    : script_path(app.replay_path),
      out_dir(app.out_dir),
      update_golden(app.update_golden),
      no_render(app.no_render),
      game(app.game),
      settings(app.settings),
      sounds_path(app.sounds_path),
      audio_out(app.audio_out),
      files(app.files) {}

namespace {

namespace fs = std::filesystem;
using replay::Expectation;

std::string trimmed(const std::string& line) {
  size_t b = line.find_first_not_of(" \t");
  size_t e = line.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : line.substr(b, e - b + 1);
}

// libpng reports a damaged PNG on stderr itself before OpenImageIO's error comes back: those
// lines are captured so that a damaged golden is one FAIL line of the report. Empty `why` = read.
std::optional<Image> load_golden(const std::string& path, std::string& why) {
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  std::FILE* sink = std::tmpfile();
  const bool captured = saved >= 0 && sink && ::dup2(::fileno(sink), STDERR_FILENO) >= 0;
  std::optional<Image> image;
  try {
    image = load_image(path);
  } catch (const InputError& e) {
    why = e.what();
  }
  std::fflush(stderr);
  if (captured) ::dup2(saved, STDERR_FILENO);
  if (saved >= 0) ::close(saved);
  if (sink) std::fclose(sink);
  // The decoder's lines, joined (InputError wrote each line end as \n): one line of the report.
  for (size_t at = why.find("\\n"); at != std::string::npos; at = why.find("\\n", at)) why.replace(at, 2, "; ");
  std::replace(why.begin(), why.end(), '\n', ' ');
  return image;
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

class ReplayPlayer {
 public:
  // Loads the script's level and checks the script's names against it; reads the golden hash
  // log; makes a GL context only when there is a frame to render.
  ReplayPlayer(const ReplayRunOptions& opt, replay::Script script);
  void run();
  void update_golden(const std::string& original_text);
  ReplayOutcome& result() { return result_; }
  const replay::Script& script() const { return script_; }

 private:
  void fail(uint64_t tick, const replay::SourceLine& src, const std::string& why);
  void pass(uint64_t tick, const replay::SourceLine& src);
  std::string log_path() const { return (fs::path(golden_dir_) / "hashes.txt").string(); }
  void report_divergence(uint64_t mismatch_tick);
  void check_log(uint64_t t, uint64_t cheap, std::optional<uint64_t> full);
  void check_hash(size_t i, uint64_t t, uint64_t cheap, uint64_t full);
  void check_hashes(uint64_t t, size_t& next_hash);
  void check_snapshot(const replay::SnapshotCheck& s, uint64_t t);
  void stage(const std::string& path, const void* data, size_t size);
  void check_run_files() const;

  const ReplayRunOptions& opt_;
  replay::Script script_;
  uint64_t last_tick_;  // the run stops after this tick's checks
  std::string level_path_;
  Settings settings_;  // the command line's, then the script's quality preset and `set` lines
  GameOptions game_options_;
  Game game_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::string golden_dir_, out_dir_;
  std::string images_dir_;        // golden PNGs: golden_dir_, or that of the script named by snapshots_like
  ImageCompareRule compare_rule_;  // the script's tolerance, else image_compare's default
  std::optional<replay::HashLog> golden_log_;
  replay::HashLog log_;
  std::vector<uint64_t> hash_values_;  // per script hash line, for --update-golden
  ReplayOutcome result_;
  bool divergence_reported_ = false;
  uint64_t last_matching_hash_tick_ = 0;
  size_t next_full_ = 0;          // golden_log_->full entries before this one are behind us
  uint64_t last_full_match_ = 0;  // the last tick whose full hash matched the log
  SoundEventTracker sounds_;       // `expect sound` lines, without an audio device
  std::unique_ptr<AudioCapture> audio_;  // --audio-out
  std::vector<SoundEvent> tick_sounds_;  // the sound events of the tick just stepped
  // --update-golden: every new golden file written and closed, renamed into place together
  // only when all of them are complete, so a failed update leaves the old goldens whole.
  std::vector<std::unique_ptr<FileWriter>> staged_;
};

ReplayPlayer::ReplayPlayer(const ReplayRunOptions& opt, replay::Script script)
    : opt_(opt),
      script_(std::move(script)),
      last_tick_(script_.last_tick()),
      level_path_(resolve_script_level(script_, data_root_of(opt.game))),
      settings_(script_settings(script_, opt.settings, data_root_of(opt.game))),
      game_options_(script_game_options(script_, settings_, opt.game)),
      game_(Game::load_level(level_path_, game_options_)) {
  check_expectation_names(script_, game_.world());
  const std::string stem = fs::path(opt.script_path).stem().string();
  golden_dir_ = !opt.golden_dir.empty() ? opt.golden_dir
                                        : (fs::path(opt.script_path).parent_path() / "golden" / stem).string();
  images_dir_ = script_.header.snapshots_like.empty()
                    ? golden_dir_
                    : (fs::path(golden_dir_).parent_path() / script_.header.snapshots_like).string();
  if (const auto& tolerance = script_.header.tolerance) {
    compare_rule_.tolerance = tolerance->max_channel_diff;
    compare_rule_.min_fraction = tolerance->min_percent / 100.0;
  }
  out_dir_ = !opt.out_dir.empty() ? opt.out_dir : (fs::path("out") / "replay" / stem).string();
  hash_values_.assign(script_.hashes.size(), 0);
  if (!opt.update_golden)
    if (const auto log = read_optional_input_file(log_path(), kMaxScriptFileBytes, "a hash log"))
      golden_log_ = replay::parse_hash_log(*log, log_path());
  check_run_files();
  if (!opt.audio_out.empty()) audio_ = std::make_unique<AudioCapture>(opt.sounds_path, settings_, opt.audio_out);
  // Only a frame to look at makes a GL context: replays without snapshots never create one.
  if (!opt.no_render && (!script_.snapshots.empty() || opt.render_every > 0)) {
    FrameRendererDesc desc;
    desc.width = script_.header.snapshot_width;
    desc.height = script_.header.snapshot_height;
    renderer_ = std::make_unique<FrameRenderer>(desc, settings_, game_);
  }
  // Output folders are checked before the first tick (core/file_writer.h).
  if (renderer_ && !script_.snapshots.empty()) check_output_dir(out_dir_, "--out");
  if (opt.update_golden) check_output_dir(golden_dir_, "golden folder");
}

// Every file the replay reads and writes, checked before the first write: no output may be an
// input. The script itself is the one file rewritten in place (--update-golden's hash values).
void ReplayPlayer::check_run_files() const {
  RunFiles files = opt_.files;
  add_level_inputs(files, game_.world(), data_root_of(opt_.game));
  files.input("--replay", opt_.script_path);
  if (opt_.update_golden) files.output("golden hash log", log_path());
  else files.input("golden hash log", log_path());
  const bool own_images = script_.header.snapshots_like.empty();
  for (const replay::SnapshotCheck& s : script_.snapshots) {
    const std::string golden = (fs::path(images_dir_) / (s.name + ".png")).string();
    if (opt_.update_golden && own_images) files.output("golden image", golden);
    else files.input("golden image", golden);
    if (opt_.no_render) continue;
    for (const char* tail : {".png", "_actual.png", "_diff.png"})
      files.output("--out", (fs::path(out_dir_) / (s.name + tail)).string());
  }
  files.check();
}

void ReplayPlayer::stage(const std::string& path, const void* data, size_t size) {
  auto file = std::make_unique<FileWriter>(path);
  file->write(data, size);
  file->close();
  staged_.push_back(std::move(file));
}

void ReplayPlayer::fail(uint64_t tick, const replay::SourceLine& src, const std::string& why) {
  ++result_.failures;
  std::printf("FAIL %s:%d: tick %llu: %s: %s\n", script_.path.c_str(), src.line, static_cast<unsigned long long>(tick),
              trimmed(src.text).c_str(), why.c_str());
}

void ReplayPlayer::pass(uint64_t tick, const replay::SourceLine& src) {
  if (!opt_.quiet)
    std::printf("ok   %s:%d: tick %llu: %s\n", script_.path.c_str(), src.line, static_cast<unsigned long long>(tick),
                trimmed(src.text).c_str());
}

// The cheap hash is compared with the golden log on every tick the log covers, so its first
// mismatch is the first diverging tick (check_log reports it on the spot). Other mismatches
// (a script's hash line, a full hash) come here: a second run from tick 0 hashes every tick
// up to it to find the first one that diverged, and dumps the state there.
void ReplayPlayer::report_divergence(uint64_t mismatch_tick) {
  if (divergence_reported_) return;
  divergence_reported_ = true;
  if (!golden_log_) {
    std::printf("  no golden hash log (%s): the first diverging tick is after tick %llu; state at tick %llu:\n%s",
                log_path().c_str(), static_cast<unsigned long long>(last_matching_hash_tick_),
                static_cast<unsigned long long>(mismatch_tick), game_.state_dump().c_str());
    return;
  }
  Game again = Game::load_level(level_path_, game_options_);
  ScriptFeeder feed(script_);
  for (uint64_t t = 0; t <= mismatch_tick && t < golden_log_->hashes.size(); ++t) {
    const uint64_t h = again.hash();
    if (h != golden_log_->hashes[t]) {
      std::printf("  first diverging tick %llu: state hash %s, golden log %s says %s; state at tick %llu:\n%s",
                  static_cast<unsigned long long>(t), replay::hex64(h).c_str(), log_path().c_str(),
                  replay::hex64(golden_log_->hashes[t]).c_str(), static_cast<unsigned long long>(t),
                  again.state_dump().c_str());
      return;
    }
    feed.step(again, t);
  }
  std::printf("  every tick up to %llu matches the golden log's cheap hash; the full state (particles) diverged "
              "first; state at tick %llu:\n%s",
              static_cast<unsigned long long>(mismatch_tick), static_cast<unsigned long long>(mismatch_tick),
              game_.state_dump().c_str());
}

// Every tick: the cheap hash against the log's entry for the tick; with `full` (checkpoint
// ticks), the full hash against the log's full entry when it has one for the tick.
void ReplayPlayer::check_log(uint64_t t, uint64_t cheap, std::optional<uint64_t> full) {
  if (!golden_log_ || divergence_reported_ || t >= golden_log_->hashes.size()) return;
  const auto& fulls = golden_log_->full;
  while (next_full_ < fulls.size() && fulls[next_full_].first < t) ++next_full_;
  std::optional<uint64_t> want_full;
  if (full && next_full_ < fulls.size() && fulls[next_full_].first == t) want_full = fulls[next_full_].second;
  const bool cheap_ok = golden_log_->hashes[t] == cheap;
  if (cheap_ok && (!want_full || *want_full == *full)) {
    if (want_full) last_full_match_ = t;
    return;
  }
  ++result_.failures;
  divergence_reported_ = true;
  if (!cheap_ok) {
    // Every earlier tick matched, so this is the first one that diverged.
    std::printf("FAIL %s: tick %llu: state differs from the golden hash log %s\n"
                "  first diverging tick %llu: state hash %s, golden log says %s; state at tick %llu:\n%s",
                script_.path.c_str(), static_cast<unsigned long long>(t), log_path().c_str(),
                static_cast<unsigned long long>(t), replay::hex64(cheap).c_str(),
                replay::hex64(golden_log_->hashes[t]).c_str(), static_cast<unsigned long long>(t),
                game_.state_dump().c_str());
    return;
  }
  std::printf("FAIL %s: tick %llu: full state hash %s, golden log %s says %s\n"
              "  the cheap hash matched every tick up to %llu; the full state (every particle) diverged after the "
              "last matching full hash at tick %llu; state at tick %llu:\n%s",
              script_.path.c_str(), static_cast<unsigned long long>(t), replay::hex64(*full).c_str(),
              log_path().c_str(), replay::hex64(*want_full).c_str(), static_cast<unsigned long long>(t),
              static_cast<unsigned long long>(last_full_match_), static_cast<unsigned long long>(t),
              game_.state_dump().c_str());
}

void ReplayPlayer::check_hash(size_t i, uint64_t t, uint64_t cheap, uint64_t full) {
  const replay::HashCheck& c = script_.hashes[i];
  uint64_t actual = c.full ? full : cheap;
  hash_values_[i] = actual;
  ++result_.checks;
  if (opt_.update_golden) return;
  if (!c.value) {
    fail(t, c.src, "hash not filled in yet; run with --update-golden to record " + replay::hex64(actual));
    return;
  }
  if (*c.value == actual) {
    last_matching_hash_tick_ = t;
    pass(t, c.src);
    return;
  }
  fail(t, c.src, "hash is " + replay::hex64(actual));
  report_divergence(t);
}

// The cheap hash runs every tick (a small part of a step); the full hash, which visits every
// particle, only at checkpoints and hash lines.
void ReplayPlayer::check_hashes(uint64_t t, size_t& hi) {
  const bool hash_line = hi < script_.hashes.size() && script_.hashes[hi].tick == t;
  if (!opt_.update_golden && !hash_line && !golden_log_) return;
  const uint64_t every = uint64_t(std::max(opt_.full_hash_every, 1));
  const bool checkpoint = t % every == 0 || t == last_tick_;
  const uint64_t cheap = game_.hash();
  const bool want_full = hash_line || (checkpoint && (opt_.update_golden || golden_log_));
  const uint64_t full = want_full ? game_.full_hash() : 0;
  if (opt_.update_golden) {
    log_.hashes.push_back(cheap);
    if (t % every == 0) log_.full.emplace_back(t, full);
  } else {
    check_log(t, cheap, want_full ? std::optional<uint64_t>(full) : std::nullopt);
  }
  for (; hi < script_.hashes.size() && script_.hashes[hi].tick == t; ++hi) check_hash(hi, t, cheap, full);
}

void ReplayPlayer::check_snapshot(const replay::SnapshotCheck& s, uint64_t t) {
  ++result_.checks;
  if (!renderer_) return;
  Image actual = renderer_->render(game_);
  ++result_.frames_rendered;
  const std::string golden = (fs::path(images_dir_) / (s.name + ".png")).string();
  const std::string written = (fs::path(out_dir_) / (s.name + ".png")).string();
  save_image(written, actual);
  const bool own_images = script_.header.snapshots_like.empty();
  if (opt_.update_golden && own_images) {
    const std::vector<uint8_t> png = encode_image(golden, actual);
    stage(golden, png.data(), png.size());
    return;
  }
  if (!input_path_exists(golden)) {
    fail(t, s.src, "no golden image " + golden + "; run with --update-golden " +
                       (own_images ? "after checking " + written
                                   : "on " + script_.header.snapshots_like + ", whose frames this script must match"));
    return;
  }
  std::error_code ec;
  if (fs::is_directory(golden, ec)) {
    fail(t, s.src, "golden image " + golden + " is a folder, not a PNG file; remove it and run --update-golden");
    return;
  }
  std::string unreadable;
  const std::optional<Image> expected = load_golden(golden, unreadable);
  if (!expected) {
    fail(t, s.src, "golden image damaged: " + unreadable + "; check " + written + " and run --update-golden");
    return;
  }
  ImageDiff d = compare_images(*expected, actual, compare_rule_);
  if (d.passed) {
    pass(t, s.src);
    return;
  }
  std::string prefix = (fs::path(out_dir_) / s.name).string();
  write_failure_images(prefix, actual, *expected);
  fail(t, s.src, d.summary() + "; wrote " + prefix + "_actual.png and " + prefix + "_diff.png");
}

void ReplayPlayer::run() {
  const uint64_t last = last_tick_;
  size_t ei = 0, hi = 0, si = 0;
  ScriptFeeder feed(script_);
  ProgressBar bar(last, !opt_.quiet);
  for (uint64_t t = 0;; ++t) {
    check_hashes(t, hi);
    for (; ei < script_.expectations.size() && script_.expectations[ei].tick == t; ++ei) {
      const Expectation& e = script_.expectations[ei];
      ++result_.checks;
      if (auto why = expectation_failure(e, game_.world(), tick_sounds_)) fail(t, e.src, *why);
      else pass(t, e.src);
    }
    for (; si < script_.snapshots.size() && script_.snapshots[si].tick == t; ++si) check_snapshot(script_.snapshots[si], t);
    if (t >= last) break;
    feed.step(game_, t);
    if (audio_) audio_->after_tick(game_.world());
    tick_sounds_ = audio_ ? audio_->session().last_events() : sounds_.collect(game_.world());
    if (renderer_ && opt_.render_every > 0 && (t + 1) % uint64_t(opt_.render_every) == 0) {
      renderer_->render(game_);
      ++result_.frames_rendered;
    }
    bar.update(t + 1);
    if (stop_requested()) {  // SIGINT or SIGTERM: at the end of this tick, its checks not made
      result_.stopped = true;
      result_.ticks = t + 1;
      break;
    }
  }
  if (!result_.stopped) result_.ticks = last;
  result_.final_hash = game_.hash();
  if (audio_) audio_->finish();
}

void ReplayPlayer::update_golden(const std::string& original_text) {
  const std::string log = replay::write_hash_log(log_);
  stage(log_path(), log.data(), log.size());
  const std::string filled = replay::fill_hash_values(original_text, script_, hash_values_);
  if (filled != original_text) stage(script_.path, filled.data(), filled.size());
  for (const auto& file : staged_) {
    file->commit();
    if (!opt_.quiet && file->path() != log_path() && file->path() != script_.path)
      std::printf("updated %s\n", file->path().c_str());
  }
  std::printf("updated %zu hash lines in %s and the hash log %s\n", script_.hashes.size(), script_.path.c_str(),
              log_path().c_str());
}

}  // namespace

ReplayOutcome play_replay(const ReplayRunOptions& opt) {
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  const std::string text = read_input_file(opt.script_path, kMaxScriptFileBytes, "a replay script");
  ReplayPlayer p(opt, replay::parse_script(text, opt.script_path, all_settings()));
  const clock::time_point ready = clock::now();
  p.run();
  ReplayOutcome& result = p.result();
  result.setup_seconds = std::chrono::duration<double>(ready - start).count();
  result.run_seconds = std::chrono::duration<double>(clock::now() - ready).count();
  if (result.stopped) {
    // The checks past the tick reached were never made: no failure for them, no golden updated.
    if (!opt.quiet || result.failures > 0)
      std::printf("%s: %d checks up to tick %llu, %d failed\n", opt.script_path.c_str(), result.checks,
                  static_cast<unsigned long long>(result.ticks), result.failures);
    result.exit_code = report_stop("at tick " + std::to_string(result.ticks) + " of " +
                                   std::to_string(p.script().last_tick()) +
                                   (opt.update_golden ? "; the golden files are unchanged" : ""));
    return result;
  }
  if (opt.update_golden) p.update_golden(text);
  if (!opt.quiet || result.failures > 0)
    std::printf("%s: %d checks, %d failed%s\n", opt.script_path.c_str(), result.checks, result.failures,
                opt.no_render && !p.script().snapshots.empty() ? " (snapshots skipped: --no-render)" : "");
  result.exit_code = result.failures > 0 ? kExitCheckFailed : kExitOk;
  return result;
}

int run_replay(const ReplayRunOptions& options) {
  ReplayOutcome r = play_replay(options);
  if (r.stopped) return r.exit_code;
  std::printf("final hash %s at tick %llu\n", replay::hex64(r.final_hash).c_str(),
              static_cast<unsigned long long>(r.ticks));
  std::fflush(stdout);
  return r.exit_code;
}

}  // namespace arc
