// Replay scripts (tests/replays/*.replay). A script that parses must also survive its own
// canonical form: parse(write(s)) has the same content, or the writer and parser disagree.
#include <cstdio>
#include <cstdlib>
#include "fuzz_target.h"
#include "game/app/all_settings.h"
#include "replay/script.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const arc::Settings known = arc::all_settings();
  arc::fuzz::expect_clean([&] {
    const arc::replay::Script s = arc::replay::parse_script(arc::fuzz::text_of(data, size), "fuzz.replay", known);
    const arc::replay::Script again = arc::replay::parse_script(arc::replay::write_script(s), "fuzz-written.replay", known);
    if (!again.same_content(s)) {
      std::fprintf(stderr, "the written script parses to different content\n");
      std::abort();
    }
  });
  return 0;
}
