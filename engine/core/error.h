// core/error.h — the one exception type for bad input.
//
// Every loader and parser (levels, effects, ships, replay scripts, assets, command line)
// throws InputError with a message that already names the place:
//   "levels/duel.json:12:7: 'seed' must be an unsigned integer"
// The executable prints it as one line and exits with code 2.
#pragma once
#include <stdexcept>
#include <string>

namespace arc {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Exit codes of the arcfire executable.
enum ExitCode : int { kExitOk = 0, kExitCheckFailed = 1, kExitBadInput = 2 };

}  // namespace arc
