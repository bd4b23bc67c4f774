// game/sim/game.h — the simulation: a pure function of (level, seed, difficulty, inputs).
//
// Game owns ships, weapons, shields, AI and the ParticleWorld. step() advances one fixed tick
// with the player's InputFrame and the tick's commands. Nothing here reads the wall clock or
// includes GL. The renderer reads state through world(); replays hash it through hash().
//
// Example, compiled as GameExamples.StepAndHash in tests/unit/game/test_game_examples.cpp:
//   Game game = Game::load_level("levels/duel.json", GameOptions{});   // InputError on bad files
//   for (int tick = 0; tick < 60; ++tick) game.step(input, commands);
//   uint64_t h = game.hash();
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "game/sim/input.h"

namespace arc {

class World;  // game/sim/world.h: ships, projectiles, particle world, level state
class ParticleStore;  // particles/particle_store.h: the memory a particle world's pools take

enum class Difficulty : uint8_t { Easy = 0, Normal = 1, Hard = 2 };
constexpr Difficulty last_enumerator(Difficulty) { return Difficulty::Hard; }
// "easy", "normal" or "hard", as level files, replay headers and the pause menu spell them.
constexpr const char* difficulty_name(Difficulty d) {
  return d == Difficulty::Easy ? "easy" : d == Difficulty::Hard ? "hard" : "normal";
}

struct GameOptions {
  Difficulty difficulty = Difficulty::Normal;
  bool difficulty_override = false;  // false: the level's own difficulty
  bool seed_override = false;
  uint64_t seed = 0;
  uint32_t particle_budget = 400000;
  int sim_threads = 1;  // ParticleConfig::threads (sim.threads); not saved or hashed: it changes no state
  int lightning_interval = 0;  // 0 = effects' own
  int substeps = 1;
  double cull_distance = 20000.0;  // particle clusters farther from the camera are not animated or drawn
  bool autopilot = false;  // the fighter AI flies the player's ship (sim.autopilot)
  std::string root_dir = ".";  // where assets/ lives (files named in levels are relative to it)
  // The briefing's choice for the player's ship: a class name ("" = the level's) and a loadout
  // "PRIMARY+SECONDARY" ("beam+torpedo"; "" = the class's own weapons). Replays record both.
  std::string ship;
  std::string loadout;
  bool operator==(const GameOptions&) const = default;
};

class Game {
 public:
  static Game load_level(const std::string& level_path, const GameOptions& options);
  // The same with its particles in `store` when it is large enough and unused (the window keeps
  // one warm, so a launch does not write a new store through); nothing simulated depends on it.
  static Game load_level(const std::string& level_path, const GameOptions& options, std::shared_ptr<ParticleStore> store);
  Game(const Game&);             // deep copy: the serialization test runs a copy beside the original
  Game& operator=(const Game&);
  // This game becomes a copy of `other` (a copy of it or of its level), reusing its memory: the
  // rollback's per-tick save and restore (game/net/rollback.h).
  void copy_state_from(const Game& other);
  Game(Game&&) noexcept;
  Game& operator=(Game&&) noexcept;
  ~Game();

  void step(const InputFrame& input, const std::vector<Command>& commands = {});
  // Network matches: which of the level's slots (LevelDef::slots; without any, the player's ship
  // alone) a pilot flies; the others fly by AI. Call before the first step_slots.
  void set_pilots(const std::vector<bool>& piloted);
  size_t slot_count() const;  // the level's slots (at least 1 where it has a player)
  // One tick of a network match: one SlotInput per slot (unpiloted slots' are ignored).
  void step_slots(const std::vector<SlotInput>& slots);
  uint64_t tick() const;
  double tick_seconds() const;
  bool paused() const;
  uint64_t hash() const;       // cheap: ships, weapons, projectiles, RNG counters, cluster summaries
  uint64_t full_hash() const;  // everything, every particle included
  std::string state_dump() const;  // readable, for the first diverging tick of a replay
  std::string summary_json() const;  // the headless --summary document

  // Serialization (for --serialization-test and save games): bytes in, bytes out.
  std::vector<uint8_t> save() const;
  static Game restore(const std::vector<uint8_t>& bytes, const std::string& level_path, const GameOptions& options);

  const World& world() const;
  World& world_mut();

 private:
  Game();
  std::unique_ptr<World> world_;
};

}  // namespace arc
