// platform/stop_request.h — SIGINT and SIGTERM as a request to stop at the next safe point.
//
// A terminal's Ctrl+C or a `kill` must leave every file a normal end leaves, so the handlers
// only record the signal: the window loop closes as with its close button and the headless
// loops stop at the end of the current tick, then write what they would have written, say
// where they stopped and exit with the shell's code for the signal (130 SIGINT, 143 SIGTERM).
// A second signal of either kind ends the process at once with _exit(128 + its number), for a
// user who does not want to wait for the writing.
//
// Example, compiled as StopRequestExample.StopAtTheEndOfATick in tests/unit/app/test_stop_request.cpp:
//   install_stop_handlers();  // once, first thing in main()
//   if (stop_requested()) return report_stop("at tick " + std::to_string(t) + " of 600");
#pragma once
#include <string>

namespace arc {

// Installs the handlers for SIGINT and SIGTERM (with SA_RESTART, so no write fails with EINTR).
void install_stop_handlers();
// The signal that asked to stop (SIGINT or SIGTERM); 0 while none has arrived.
int stop_signal();
inline bool stop_requested() { return stop_signal() != 0; }
// 128 + stop_signal(): 130 for SIGINT, 143 for SIGTERM.
int stop_exit_code();
// "SIGINT", "SIGTERM".
const char* stop_signal_name();
// One line on stderr, "arcfire: stopped by SIGINT " + where; returns stop_exit_code().
int report_stop(const std::string& where);

}  // namespace arc
