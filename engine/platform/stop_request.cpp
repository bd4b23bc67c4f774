// platform/stop_request.cpp — the SIGINT/SIGTERM handlers: record the first, _exit on a second.
#include "platform/stop_request.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>

namespace arc {
namespace {

// Read and written from the handler: it must be lock-free to be async-signal-safe.
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int signo) {
  if (g_stop_signal.exchange(signo) != 0) _exit(128 + signo);
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int stop_signal() { return g_stop_signal.load(); }

int stop_exit_code() { return 128 + stop_signal(); }

const char* stop_signal_name() {
  switch (stop_signal()) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
  }
  return "a signal";
}

int report_stop(const std::string& where) {
  std::fflush(stdout);
  std::fprintf(stderr, "arcfire: stopped by %s %s\n", stop_signal_name(), where.c_str());
  return stop_exit_code();
}

}  // namespace arc
