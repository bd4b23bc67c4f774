// game/net/net_settings.h — the net.* settings keys, registered with every other module's.
#pragma once

namespace arc {

class Settings;

// net.input_delay, net.timeout and the link simulation a match's packets may pass through
// (net.sim_latency_ms, net.sim_jitter_ms, net.sim_loss: tests on the loopback).
void register_net_settings(Settings& s);

}  // namespace arc
