// Binary world snapshots, restored as Game::restore does (into levels/duel.json). The frame's
// size and checksum are rewritten to fit the bytes, so mutations reach the field reader instead
// of stopping at the checksum; the frame checks themselves are covered by the unit tests.
#include <vector>
#include "core/snapshot_io.h"
#include "fuzz_target.h"
#include "game/sim/game.h"
#include "core/data_root.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arc::snapshot;
  std::vector<uint8_t> bytes(data, data + size);
  if (size >= kFrameHeader + kFrameTrailer) {
    const uint64_t payload = size - kFrameHeader - kFrameTrailer;
    for (int i = 0; i < 8; ++i) bytes[12 + size_t(i)] = uint8_t(payload >> (8 * i));
    const uint64_t sum = checksum(bytes.data() + kFrameHeader, size_t(payload));
    for (int i = 0; i < 8; ++i) bytes[size - kFrameTrailer + size_t(i)] = uint8_t(sum >> (8 * i));
  }
  arc::GameOptions options;
  options.root_dir = arc::data_root();
  arc::fuzz::expect_clean([&] { arc::Game::restore(bytes, arc::data_root() + "/levels/duel.json", options); });
  return 0;
}
