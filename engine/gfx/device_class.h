// gfx/device_class.h — which kind of device draws, from its GL_RENDERER string (no GL).
//
// A software rasteriser (Mesa's llvmpipe, softpipe, swrast) is fill-bound and wants the CPU to
// trim every particle it can; a hardware GPU is the other way round. The renderer's "auto"
// settings and the first-start look follow this (names tested in tests/unit/gfx/test_particle_prep.cpp).
#pragma once
#include <string_view>

namespace arc {

bool is_software_rasteriser(std::string_view gl_renderer);

}  // namespace arc
