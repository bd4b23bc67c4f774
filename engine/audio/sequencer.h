// audio/sequencer.h — renders a music piece (audio/music_def.h) into stereo samples.
//
// Every note of every track is synthesised on its instrument (oscillator pair or keyed noise,
// pitch drop, ADSR, two-pole low-pass with an envelope, one-pole high-pass), panned with equal
// power and summed; a ping-pong echo follows. A looping piece's tails (releases, echoes) wrap
// into its start, so it loops without a seam; a one-shot gets room for its tail. The piece is
// scaled to a set RMS (times its gain), so every piece sits at the same level and the
// crossfades between them do not jump. A pure function of the def and the rate.
#pragma once
#include <vector>

#include "audio/music_def.h"

namespace arc {

constexpr double kMusicRms = 0.12;  // a piece's RMS before its gain (about −18 dBFS)

// Interleaved stereo floats; a loop's length is exactly its bars at its tempo.
std::vector<float> render_piece(const MusicLibraryDef& lib, const MusicPieceDef& piece, int sample_rate);

}  // namespace arc
