// Scenes several benchmark files measure.
#pragma once
#include <memory>
#include <string>

#include "gfx/renderer.h"
#include "platform/platform.h"

namespace arc::bench {

// A level (path relative to the source tree) simulated `ticks` ticks from its start with the
// default settings and no input, its models and sprites loaded into `r`, and the view built for
// width×height from the level's camera without the HUD (its labels are text drawn after the
// particle pass). The gallery at tick 240 has explosions, beams, sparks, trails and shields all
// alive; the arena at tick 600 is the battle in full swing, seen from the chase camera.
RenderView level_view(Renderer& r, const std::string& level, int ticks, int width, int height);

// The EGL context a render scene draws in, or nullptr after printing "skipped: ..." (a machine
// without EGL runs the other scenes).
std::unique_ptr<HeadlessContext> context_or_skip();

// Whether a GL renderer string names one of Mesa's software rasterisers (llvmpipe, softpipe),
// whose GL_TIME_ELAPSED does not cover rasterisation.
bool software_rasteriser(const std::string& gl);

// ARCFIRE_BENCH_ROUNDS (1..10000) when set, else `fallback`; a bad value prints one line naming
// it and what is allowed, and exits 2.
int rounds_from_env(int fallback);

}  // namespace arc::bench
