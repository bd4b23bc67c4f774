// The stop request (platform/stop_request.h): the first SIGINT or SIGTERM is recorded, a second
// ends the process at once. Each case runs in a child process (a death test): a request cannot
// be taken back, and the replays of the other tests would stop at their first tick.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "platform/stop_request.h"

namespace arc {
namespace {

using ::testing::ExitedWithCode;

// Exits with the code the program would: 130 / 143 when the signal was recorded, else 1.
void raise_once(int signo) {
  install_stop_handlers();
  if (stop_requested()) std::_Exit(1);
  std::raise(signo);
  std::_Exit(stop_signal() == signo ? stop_exit_code() : 1);
}

TEST(StopRequest, SigintIsRecordedAsExitCode130) { EXPECT_EXIT(raise_once(SIGINT), ExitedWithCode(130), ""); }

TEST(StopRequest, SigtermIsRecordedAsExitCode143) { EXPECT_EXIT(raise_once(SIGTERM), ExitedWithCode(143), ""); }

TEST(StopRequest, ASecondSignalEndsTheProcessAtOnce) {
  auto twice = [] {
    install_stop_handlers();
    std::raise(SIGINT);
    std::raise(SIGTERM);
    std::_Exit(1);  // not reached: the second signal _exits with 128 + SIGTERM
  };
  EXPECT_EXIT(twice(), ExitedWithCode(143), "");
}

TEST(StopRequest, ReportNamesTheSignalAndWhere) {
  auto report = [] {
    install_stop_handlers();
    std::raise(SIGTERM);
    std::_Exit(report_stop("at tick 7 of 9"));
  };
  EXPECT_EXIT(report(), ExitedWithCode(143), "^arcfire: stopped by SIGTERM at tick 7 of 9\n$");
}

// The banner's example: a loop that checks for a stop at the end of each tick.
TEST(StopRequestExample, StopAtTheEndOfATick) {
  auto run = []() -> int {
    install_stop_handlers();  // once, first thing in main()
    for (int t = 1; t <= 600; ++t) {
      if (t == 12) std::raise(SIGINT);  // Ctrl+C during tick 12
      if (stop_requested()) return report_stop("at tick " + std::to_string(t) + " of 600");
    }
    return 0;
  };
  EXPECT_EXIT(std::_Exit(run()), ExitedWithCode(130), "stopped by SIGINT at tick 12 of 600");
}

}  // namespace
}  // namespace arc
