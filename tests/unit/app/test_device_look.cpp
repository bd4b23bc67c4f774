// The first start's quality preset by device (game/app/device_look.h), from renderer names as
// drivers report them: a GPU gets the full look, a software rasteriser the built-in settings.
#include <gtest/gtest.h>

#include "game/app/device_look.h"
#include "game/app/user_settings.h"

namespace arc {
namespace {

TEST(DeviceLook, GpusGetTheHighPreset) {
  for (const char* gpu : {"NVIDIA H200/PCIe/SSE2", "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)",
                          "Mesa Intel(R) UHD Graphics 620 (KBL GT2)", "Apple M2"}) {
    const QualityChoice c = device_default_quality(gpu);
    EXPECT_EQ(c.preset, "high") << gpu;
    EXPECT_NE(c.why.find("GPU"), std::string::npos) << c.why;
  }
  EXPECT_EQ(device_default_quality("AMD Radeon RX 7900 XTX (radeonsi, navi31)").why, "high: chosen for a GPU (AMD Radeon RX 7900 XTX)");
}

TEST(DeviceLook, SoftwareRasterisersKeepTheDefault) {
  for (const char* soft : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Mesa X11 swrast", "Google SwiftShader"}) {
    const QualityChoice c = device_default_quality(soft);
    EXPECT_EQ(c.preset, kDefaultQuality) << soft;
    EXPECT_NE(c.why.find("software rasteriser"), std::string::npos) << c.why;
  }
  EXPECT_EQ(device_default_quality("llvmpipe (LLVM 15.0.6, 256 bits)").why, "default: chosen for a software rasteriser (llvmpipe)");
  EXPECT_EQ(device_default_quality("").preset, kDefaultQuality);
}

}  // namespace
}  // namespace arc
