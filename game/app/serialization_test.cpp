// The serialization test: a game and its save-and-restored copy stepped side by side.
#include "game/app/serialization_test.h"

#include <cstdio>
#include <optional>

#include "core/error.h"
#include "game/app/all_settings.h"
#include "game/app/script_feeder.h"
#include "platform/stop_request.h"
#include "replay/script.h"

namespace arc {

SerializationTestOptions::SerializationTestOptions(const AppOptions& app)
    : level_path(app.level), game(app.game), settings(app.settings), every(app.serialization_test) {
  if (app.ticks > 0) ticks = app.ticks;
}

int run_serialization_test(const SerializationTestOptions& opt) {
  if (opt.every < 1) throw InputError("--serialization-test: N must be at least 1, got " + std::to_string(opt.every));
  std::optional<replay::Script> script;
  std::string level = opt.level_path;
  GameOptions game_options = opt.game;
  uint64_t last = static_cast<uint64_t>(opt.ticks);
  if (!opt.script_path.empty()) {
    script = replay::load_script(opt.script_path, all_settings());
    level = resolve_script_level(*script, data_root_of(opt.game));
    game_options = script_game_options(*script, script_settings(*script, opt.settings, data_root_of(opt.game)), opt.game);
    last = script->last_tick();
  }
  if (uint64_t(opt.every) > last)
    throw InputError("--serialization-test: N (" + std::to_string(opt.every) + ") is larger than the run (" +
                     std::to_string(last) + " ticks), so nothing would be saved; use N up to " +
                     std::to_string(last) + " or more --ticks");
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
    if (stop_requested())  // SIGINT or SIGTERM: the ticks compared so far were equal
      return report_stop("at tick " + std::to_string(t) + " of " + std::to_string(last) + " after " +
                         std::to_string(saves) + " save/restore cycles, hashes equal so far");
    feed_original.step(original, t);
    if (restored) feed_restored.step(*restored, t);
  }
  std::printf("serialization test: %d save/restore cycles, every %lld ticks, hashes equal on every tick\n", saves,
              static_cast<long long>(opt.every));
  std::printf("final hash %s at tick %llu\n", replay::hex64(original.hash()).c_str(),
              static_cast<unsigned long long>(last));
  return kExitOk;
}

}  // namespace arc
