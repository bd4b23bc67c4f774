// audio/sound_library.h — loads and validates assets/sounds/sounds.json into SoundLibraryDef.
//
// Errors are one line `path:line:col: what is wrong and what is allowed` (InputError), like
// every other data file; the caller exits 2 at start-up, or keeps the last good library when
// a hot reload fails.
//
// Example, compiled as AudioExamples.SynthesiseOne in tests/unit/audio/test_audio_examples.cpp:
//   SoundLibraryDef lib = load_sound_library("assets/sounds/sounds.json");
//   std::vector<float> boom = synthesise(*lib.find("explosion"), 48000);   // audio/synth.h
#pragma once
#include <string>

#include "audio/sound_def.h"

namespace arc {

SoundLibraryDef load_sound_library(const std::string& path);
SoundLibraryDef parse_sound_library(const std::string& text, const std::string& path);

}  // namespace arc
