// core/data_root.h — the folder the game's data (assets/, levels/, shaders/) is read from.
//
// One data root per process, resolved at start in this order:
//   1. --data DIR on the command line,
//   2. the ARCFIRE_DATA environment variable,
//   3. <folder of the executable>/../share/arcfire, when it exists (an installed game),
//   4. the source tree named by <folder of the executable>/arcfire-data-root, a one-line file
//      CMake writes into the build folder (a development build; a moved or installed program
//      has no such file beside it).
// The folder must hold levels/, assets/ and shaders/; otherwise InputError names the folder and
// where it came from. Nothing here is compiled in: the program and its tests find the data from
// where they run, so a build can be moved, installed or packaged.
//
// Example, compiled as DataRootExample.ResolveAndSet in tests/unit/core/test_data_root.cpp:
//   const DataRoot root = resolve_data_root(cli_value, std::getenv("ARCFIRE_DATA"), executable_path());
//   set_data_root(root.dir);  // what data_root() answers from now on
#pragma once
#include <string>

namespace arc {

struct DataRoot {
  std::string dir;     // absolute, normalised
  std::string source;  // where it came from, for messages and --version: "--data", "ARCFIRE_DATA", ...
};

// The name of the file a development build writes beside its executables.
inline constexpr const char* kDataRootFile = "arcfire-data-root";

// The order above; `env_value` may be null (unset). Throws InputError, one line, when the chosen
// folder is not a data folder or when no source gives one.
DataRoot resolve_data_root(const std::string& cli_value, const char* env_value, const std::string& exe_path);

// The running program's file (/proc/self/exe); "" when it cannot be read.
std::string executable_path();

// The folder named by <exe folder>/arcfire-data-root ("" without that file): the source tree of
// a development build, which tests also read their own inputs from (tests/, engine/ sources).
std::string build_source_tree(const std::string& exe_path = executable_path());

// The process's data root: the one set_data_root() named (arcfire sets it from its command line),
// else resolved once from ARCFIRE_DATA and the executable (tests, benchmarks). Throws InputError
// when there is none.
std::string data_root();
void set_data_root(const std::string& dir);

}  // namespace arc
