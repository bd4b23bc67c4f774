// Network packets (game/net/packet.h): what decode() accepts encodes back to the same bytes,
// and a host peer takes every packet as if a joined pilot (slot 1) sent it.
#include <cstdlib>

#include "core/data_root.h"
#include "fuzz_target.h"
#include "game/net/net_peer.h"
#include "game/net/packet.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string why;
  std::optional<arc::net::Decoded> d = arc::net::decode(data, size, &why);
  if (d) {
    const std::vector<uint8_t> again = arc::net::encode(d->packet, d->seq);
    if (again != std::vector<uint8_t>(data, data + size)) {
      std::fprintf(stderr, "a decoded packet encodes to other bytes\n");
      std::abort();
    }
  } else if (why.empty() || why.find('\n') != std::string::npos) {
    std::fprintf(stderr, "a refusal needs one line saying why\n");
    std::abort();
  }
  static arc::NetPeer host = [] {
    arc::GameOptions options;
    options.root_dir = arc::data_root();
    return arc::NetPeer(arc::Game::load_level(arc::data_root() + "/levels/duel.json", options),
                        arc::PeerConfig{.slots = 2, .local_slot = 0, .host = true});
  }();
  static double now = 0;
  host.receive(1, data, size, now += 1.0);
  host.frame(arc::SlotInput{}, now);
  host.take_outgoing();
  return 0;
}
