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

// The message is always one line: control characters that a file smuggled into it (a key or a
// value holding an escaped newline, echoed back in "got ...") are written as \n, \r, \t or \xNN.
struct InputError : std::runtime_error {
  explicit InputError(const std::string& message) : std::runtime_error(one_line(message)) {}

  static std::string one_line(const std::string& message) {
    std::string out;
    out.reserve(message.size());
    for (const char c : message) {
      const auto u = static_cast<unsigned char>(c);
      if (c == '\n') out += "\\n";
      else if (c == '\r') out += "\\r";
      else if (c == '\t') out += "\\t";
      else if (u < 0x20 || u == 0x7f) {
        const char* hex = "0123456789abcdef";
        out += "\\x";
        out += hex[u >> 4];
        out += hex[u & 15];
      } else {
        out += c;
      }
    }
    return out;
  }
};

// Exit codes of the arcfire executable.
enum ExitCode : int { kExitOk = 0, kExitCheckFailed = 1, kExitBadInput = 2 };

}  // namespace arc
