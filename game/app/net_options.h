// game/app/net_options.h — the network match's command line: --host, --join, --port, --players,
// --name, --net-pilot and --match-record (net_options.cpp, run by net_run.cpp).
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace arc {

struct NetOptions {
  bool host = false;
  std::string join;            // HOST[:PORT]
  int port = 27960;
  int players = 2;             // pilots, the host's included (a headless host without --net-pilot flies none)
  std::string name;            // the pilot's name ("" : "Pilot")
  std::string pilot;           // "scripted": the deterministic test pilot; "": no input
  std::string match_record;    // where the match's record goes ("" : net_match_SLOT.replay in the working folder)
  bool active() const { return host || !join.empty(); }
};

void define_net_options(CLI::App& app, NetOptions& n);

}  // namespace arc
