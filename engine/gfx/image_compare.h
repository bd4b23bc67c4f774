// gfx/image_compare.h — compares rendered images against goldens (no GL; tests reuse it).
//
// Rule: images match when max channel difference ≤ tolerance (default 5/255) on at least
// min_fraction (default 99.9 %) of pixels. On failure write_failure_images() saves the actual
// image and an amplified difference image as PNG beside the test output.
//
// Example, compiled as GfxCpuExamples.CompareImages in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   ImageDiff d = compare_images(expected, actual);
//   if (!d.passed) write_failure_images("build/test-output/soft_edges", actual, expected);
#pragma once
#include <string>

#include "assets/image.h"

namespace arc {

struct ImageCompareRule {
  int tolerance = 5;             // per channel, in 1/255 steps
  double min_fraction = 0.999;   // of pixels within tolerance
};

struct ImageDiff {
  bool passed = false;
  bool size_mismatch = false;
  double fraction_within = 0;  // of pixels whose max channel diff ≤ tolerance
  int max_diff = 0;            // largest channel difference seen
  std::string summary() const;
};

ImageDiff compare_images(const Image& expected, const Image& actual, const ImageCompareRule& rule = {});
Image difference_image(const Image& expected, const Image& actual);  // |a−b|·8, alpha 255
// Peak signal-to-noise ratio of the RGB channels in dB, 10·log10(255² / mean squared error);
// +infinity for identical images, NaN when the sizes differ.
double psnr_db(const Image& a, const Image& b);
// Writes <prefix>_actual.png and <prefix>_diff.png (diff only when the sizes match).
void write_failure_images(const std::string& prefix, const Image& actual, const Image& expected);

}  // namespace arc
