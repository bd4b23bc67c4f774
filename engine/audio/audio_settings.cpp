#include "audio/audio_settings.h"

#include "core/settings.h"

namespace arc {

void register_audio_settings(Settings& s) {
  s.define_number("audio.volume", 0.8, 0.0, 1.0, "master volume; no cost");
  s.define_number("audio.effects_volume", 1.0, 0.0, 1.0,
                  "volume of the game's positional sounds, under the master; no cost");
  s.define_flag("audio.mute", false, "no sound at all (M toggles it in the game); no cost");
  s.define_integer("audio.voices", 32, 4, 128,
                   "sounds playing at once; beyond it the lowest priority (sparks before explosions) fades out;"
                   " cheap (mixing CPU time per voice)");
}

}  // namespace arc
