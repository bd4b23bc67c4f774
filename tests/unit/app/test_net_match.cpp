// tests/unit/app/test_net_match.cpp — NetMatch (game/app/net_match.h) over ENet on the loopback
// in one process: a pilot joins the host's lobby, is listed with its name and slot, picks
// another slot, the host launches, and both step the match to the same hashes; a forced desync
// and the host leaving are said; a pilot with a bad name is refused before any socket opens.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <unistd.h>

#include "core/data_root.h"
#include "core/error.h"
#include "game/app/net_match.h"

namespace arc {
namespace {

double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

NetMatch::Config host_config(int port) {
  NetMatch::Config c;
  c.host = true;
  c.level = data_root() + "/levels/arena.json";
  c.port = port;
  c.name = "Host";
  c.game.root_dir = data_root();
  return c;
}

// Polls both until `done` or 5 s pass.
template <class F>
bool poll_until(NetMatch& a, NetMatch& b, F done) {
  const double until = now_ms() + 5000;
  while (!done() && now_ms() < until) {
    a.poll(now_ms()), b.poll(now_ms());
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

TEST(NetMatch, HostAndJoin) {
  const int port = 40000 + getpid() % 20000;
  NetMatch host(host_config(port));
  NetMatch::Config jc;
  jc.join = "127.0.0.1:" + std::to_string(port);
  jc.name = "Ann";
  jc.game.root_dir = data_root();
  NetMatch pilot(jc);
  ASSERT_TRUE(poll_until(host, pilot, [&] { return host.pilots_in() == 2 && pilot.phase() == NetMatch::Phase::Lobby &&
                                                   pilot.pilots().size() > 1 && pilot.pilots()[1].name == "Ann"; }))
      << host.status() << " / " << pilot.status();
  EXPECT_EQ(pilot.local_slot(), 1);
  EXPECT_TRUE(pilot.pilots()[1].you);
  EXPECT_EQ(pilot.pilots()[0].name, "Host");
  EXPECT_EQ(pilot.pilots()[1].team, host.pilots()[1].team);
  // A pick of a free slot moves the pilot there on both sides.
  pilot.pick_slot(3);
  ASSERT_TRUE(poll_until(host, pilot, [&] { return pilot.local_slot() == 3 && host.pilots()[3].name == "Ann"; }));
  EXPECT_TRUE(host.pilots()[1].name.empty());
  ASSERT_TRUE(host.launch());
  ASSERT_TRUE(poll_until(host, pilot, [&] { return pilot.phase() == NetMatch::Phase::Playing; })) << pilot.status();
  // Both fly 120 ticks with no input and agree on every hash they compared.
  const double until = now_ms() + 20000;
  while (now_ms() < until && (host.peer().session().final_tick() < 120 || pilot.peer().session().final_tick() < 120)) {
    host.poll(now_ms()), pilot.poll(now_ms());
    host.frame(SlotInput{}, now_ms()), pilot.frame(SlotInput{}, now_ms());
    std::this_thread::sleep_for(std::chrono::milliseconds(4));
  }
  ASSERT_GE(pilot.peer().session().final_tick(), 120);
  EXPECT_EQ(host.peer().session().hash_at(120), pilot.peer().session().hash_at(120));
  EXPECT_FALSE(host.peer().desync_tick());
  EXPECT_FALSE(pilot.peer().desync_tick());
}

// One peer's state altered at tick 60: both stop with "desync at tick 60" for the screen, and
// the host's leaving reaches the pilot as the match's end when there is no desync.
TEST(NetMatch, ADesyncAndTheHostLeavingAreSaid) {
  for (bool desync : {true, false}) {
    const int port = 40000 + getpid() % 20000 + (desync ? 2 : 3);
    NetMatch host(host_config(port));
    NetMatch::Config jc;
    jc.join = "127.0.0.1:" + std::to_string(port);
    jc.name = "Ann";
    jc.game.root_dir = data_root();
    NetMatch pilot(jc);
    ASSERT_TRUE(poll_until(host, pilot, [&] { return host.pilots_in() == 2; }));
    ASSERT_TRUE(host.launch());
    ASSERT_TRUE(poll_until(host, pilot, [&] { return pilot.phase() == NetMatch::Phase::Playing; }));
    if (desync) pilot.peer_mut().corrupt_at(60);
    const double until = now_ms() + 20000;
    while (now_ms() < until && pilot.phase() == NetMatch::Phase::Playing) {
      host.poll(now_ms()), pilot.poll(now_ms());
      host.frame(SlotInput{}, now_ms()), pilot.frame(SlotInput{}, now_ms());
      if (!desync && host.peer().session().tick() == 90) host.finish(testing::TempDir() + "net_match_host.replay");
      std::this_thread::sleep_for(std::chrono::milliseconds(4));
    }
    ASSERT_EQ(pilot.phase(), NetMatch::Phase::Over);
    const std::vector<std::string> said = pilot.take_messages();
    ASSERT_FALSE(said.empty());
    if (desync) EXPECT_EQ(said.back(), "desync at tick 60");
    else EXPECT_EQ(said.back().rfind("The host left at tick", 0), 0u) << said.back();
  }
}

TEST(NetMatch, ABadNameIsRefused) {
  NetMatch::Config c = host_config(40000 + getpid() % 20000 + 1);
  c.name = "";
  EXPECT_THROW(NetMatch{c}, InputError);
  c.name = std::string(25, 'a');
  EXPECT_THROW(NetMatch{c}, InputError);
}

}  // namespace
}  // namespace arc
