// Quality preset files (assets/settings/quality.json): the menu lists the presets, --quality
// applies one.
#include "fuzz_target.h"
#include "core/settings.h"
#include "game/app/all_settings.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text = arc::fuzz::text_of(data, size);
  arc::fuzz::expect_clean([&] {
    const std::vector<std::string> names = arc::Settings::preset_names_text(text, "fuzz.json");
    arc::Settings s = arc::all_settings();
    s.apply_preset_text(text, "fuzz.json", names.empty() ? std::string("high") : names.front());
  });
  return 0;
}
