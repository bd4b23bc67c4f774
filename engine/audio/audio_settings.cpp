#include "audio/audio_settings.h"

#include "core/settings.h"

namespace arc {

void register_audio_settings(Settings& s) {
  s.define_number("audio.volume", 0.8, 0.0, 1.0, "master volume; no cost");
  s.define_number("audio.effects_volume", 1.0, 0.0, 1.0,
                  "volume of the game's positional sounds, under the master; no cost");
  s.define_number("audio.music_volume", 1.0, 0.0, 1.0, "volume of the music, under the master; no cost");
  s.define_number("audio.weapons_volume", 1.0, 0.0, 1.0, "volume of beams, missiles, plasma and flares; no cost");
  s.define_number("audio.impacts_volume", 1.0, 0.0, 1.0, "volume of hits and explosions; no cost");
  s.define_number("audio.engines_volume", 1.0, 0.0, 1.0, "volume of engines and afterburners; no cost");
  s.define_number("audio.ui_volume", 1.0, 0.0, 1.0, "volume of menu clicks, lock tones and warnings; no cost");
  s.define_number("audio.voice_volume", 1.0, 0.0, 1.0, "volume of the radio voices; no cost");
  s.define_flag("audio.subtitles", true, "the radio's lines written on the HUD while they are spoken; no cost");
  s.define_flag("audio.mute", false, "no sound at all (M toggles it in the game); no cost");
  s.define_integer("audio.voices", 32, 4, 128,
                   "sounds playing at once; beyond it the lowest priority (sparks before explosions) fades out;"
                   " cheap (mixing CPU time per voice)");
}

}  // namespace arc
