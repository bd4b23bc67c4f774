// tests/fuzz/fuzz_target.h — shared by the libFuzzer targets in this folder.
//
// Each target feeds bytes to the entry point the game uses for one kind of file. A clean
// InputError is the expected answer to bad input and is swallowed; anything else (another
// exception, a sanitizer report, a hang, a crash) is a finding. The same sources are compiled
// twice: with -fsanitize=fuzzer in build-fuzz/ (tools/fuzz.sh), and against regression_main.cpp
// in the normal build, where ctest feeds every file of the target's corpus once.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"

namespace arc::fuzz {

inline std::string text_of(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Runs `load`; InputError with a one-line message is a correct answer, any other exception
// escapes to libFuzzer.
// ARCFIRE_FUZZ_VERBOSE=1 prints each answer (to see what a corpus file is refused for).
template <typename F>
void expect_clean(F&& load) {
  static const bool verbose = std::getenv("ARCFIRE_FUZZ_VERBOSE") != nullptr;
  try {
    load();
    if (verbose) std::fprintf(stderr, "accepted\n");
  } catch (const InputError& e) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    // The command line prints the message as the one line of a bad-input exit.
    if (std::string(e.what()).find_first_of("\n\r") != std::string::npos) {
      std::fprintf(stderr, "the error message spans several lines: %s\n", e.what());
      std::abort();
    }
  }
}

}  // namespace arc::fuzz
