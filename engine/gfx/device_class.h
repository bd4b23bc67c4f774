// gfx/device_class.h — which kind of device draws, from its GL_RENDERER string (no GL).
//
// A software rasteriser (Mesa's llvmpipe, softpipe, swrast) is fill-bound and wants the CPU to
// trim every particle it can; a hardware GPU is the other way round. The renderer's "auto"
// settings and the first-start look follow this.
//   is_software_rasteriser("llvmpipe (LLVM 15.0.6, 256 bits)")  // true
//   is_software_rasteriser("NVIDIA H200/PCIe/SSE2")             // false
#pragma once
#include <string_view>

namespace arc {

bool is_software_rasteriser(std::string_view gl_renderer);

}  // namespace arc
