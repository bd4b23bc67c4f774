// game/net/net_settings.cpp — the net.* settings keys.
#include "game/net/net_settings.h"

#include "core/settings.h"

namespace arc {

void register_net_settings(Settings& s) {
  s.define_integer("net.input_delay", 0, 0, 4, "ticks a network match holds the pilot's own input back; more: fewer rollbacks");
  s.define_number("net.timeout", 5.0, 1.0, 60.0, "seconds without a word before a pilot is dropped to the AI");
  s.define_number("net.sim_latency_ms", 0.0, 0.0, 1000.0, "network match: added one-way delay per packet sent (tests)");
  s.define_number("net.sim_jitter_ms", 0.0, 0.0, 500.0, "network match: ± random delay per packet sent (tests)");
  s.define_number("net.sim_loss", 0.0, 0.0, 0.5, "network match: share of unreliable packets dropped on send (tests)");
}

}  // namespace arc
