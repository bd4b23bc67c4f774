// audio/audio_settings.h — the audio.* settings keys, registered by the module that reads them.
#pragma once

namespace arc {

class Settings;

// Defines audio.volume, audio.effects_volume, the group volumes (audio.music_volume,
// weapons, impacts, engines, ui, voice), audio.subtitles, audio.mute and audio.voices (never
// part of the simulation or its hash) at their defaults.
void register_audio_settings(Settings& s);

}  // namespace arc
