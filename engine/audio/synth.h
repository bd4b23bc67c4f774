// audio/synth.h — turns a SoundDef into mono float samples in [-1, 1].
//
// Each layer is an oscillator (sine, square, saw, triangle; pitch swept exponentially from
// freq to freq_end) or white noise from a keyed hash of (seed, layer, sample), so the result is a
// pure function of the def and the rate. A layer passes a one-pole high-pass and low-pass,
// an optional burst gate (the beam's crackle rhythm) with 2 ms ramps, and its envelope
// (linear attack, hold, power-curve decay). One-shots end at zero; a loop's tail is crossfaded
// into its head so the seam does not click. The sum is scaled to peak at 0.9; the def's gain is applied when it plays.
#pragma once
#include <vector>

#include "audio/sound_def.h"

namespace arc {

std::vector<float> synthesise(const SoundDef& def, int sample_rate);

}  // namespace arc
