// game/app/net_run.h — `arcfire --host` / `--join`: a network match over ENet; every peer
// writes the match as a replay script (game/net/match_record.h) that `--replay` plays.
//
// Topology: every pilot connects to the host, and the host relays each pilot's packets to the
// others (a star). One connection per pilot goes through NAT and firewalls where a full mesh
// would need each pair to reach each other, the host can check every pilot's packets for its
// slot and rate, and the host alone decides drops; the relay adds one hop of latency between
// two pilots, which rollback hides. The host flies slot 0; pilots take the next slots in order.
//
// Exit codes: 0 the match ran to its end (or the host left), 1 a desync (its tick on stderr;
// net_dump_SLOT.txt and the record are written), 2 bad input, a refused join or no host,
// 130 / 143 stopped by SIGINT / SIGTERM (the others told, the record of the match so far written).
// The loop is NetMatch's (game/app/net_match.h), the window's own, driven at 60 Hz.
#pragma once

namespace arc {

struct AppOptions;

int run_net(const AppOptions& options);

}  // namespace arc
