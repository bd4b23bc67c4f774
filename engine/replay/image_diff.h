// replay/image_diff.h — golden-image comparison on plain RGBA8 pixels (CPU, no GL).
//
// A frame matches its golden when at least `min_fraction` of pixels differ by at most
// `max_channel_diff` in every channel (Filament renderdiff style tolerances; DESIGN.md:
// 5/255 on 99.9%). The diff image shows failing pixels in red over a dimmed copy of the
// golden, so a reviewer sees where the frames differ.
//
//   ImageDiff d = compare_rgba8(actual.rgba, golden.rgba, w, h);
//   if (!d.passed) save both d.diff_rgba and the actual frame.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc::replay {

struct ImageTolerance {
  int max_channel_diff = 5;      // in 0..255
  double min_fraction = 0.999;   // of pixels within max_channel_diff
};

struct ImageDiff {
  bool passed = false;
  uint64_t pixels = 0;
  uint64_t failing_pixels = 0;
  int max_diff = 0;                // largest channel difference seen
  std::vector<uint8_t> diff_rgba;  // same size as the inputs
  std::string describe() const;    // "12 of 230400 pixels (0.005%) differ by more than 5/255, max 80"
};

// Both buffers are width*height*4 bytes; throws std::invalid_argument on a size mismatch
// (callers check sizes first and report them as a failure of their own).
ImageDiff compare_rgba8(const std::vector<uint8_t>& actual, const std::vector<uint8_t>& golden, int width,
                        int height, const ImageTolerance& tolerance = {});

}  // namespace arc::replay
