// Writes world snapshots of levels/duel.json at a few ticks into the folder given, as seeds
// for fuzz_snapshot: `build/fuzz_snapshot_seeds tests/fuzz/corpus/snapshot`.
#include <cstdio>
#include <fstream>
#include <string>
#include "game/sim/game.h"
#include "core/data_root.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_snapshot_seeds FOLDER\n");
    return 2;
  }
  arc::GameOptions options;
  options.root_dir = arc::data_root();
  arc::Game game = arc::Game::load_level(arc::data_root() + "/levels/duel.json", options);
  arc::InputFrame fire{};
  fire.buttons = 1;
  for (int tick : {0, 30, 240}) {
    while (game.tick() < uint64_t(tick)) game.step(fire);
    const std::vector<uint8_t> bytes = game.save();
    std::ofstream out(std::string(argv[1]) + "/duel_tick" + std::to_string(tick) + ".snap", std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  }
  return 0;
}
