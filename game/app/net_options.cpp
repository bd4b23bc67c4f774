// game/app/net_options.cpp — the network options of the arcfire command line.
#include "game/app/net_options.h"

#include <CLI/CLI.hpp>

namespace arc {

void define_net_options(CLI::App& app, NetOptions& n) {
  app.add_flag("--host", n.host, "host a network match of --level (pilots join with --join); --headless: a server");
  app.add_option("--join", n.join, "join the network match hosted at HOST[:PORT]");
  app.add_option("--port", n.port, "network match: the UDP port to host on or join (default 27960)")->check(CLI::Range(1, 65535));
  app.add_option("--players", n.players, "host: pilots in the match, the host's own included (1..8, default 2)")
      ->check(CLI::Range(1, 8));
  app.add_option("--name", n.name, "network match: the pilot's name (up to 24 printable characters)");
  app.add_option("--net-pilot", n.pilot, "headless network match: 'scripted' flies the deterministic test pilot")
      ->check(CLI::IsMember({"scripted"}));
  app.add_option("--match-record", n.match_record, "network match: write the match record (a replay script of all pilots' inputs) here");
}

}  // namespace arc
