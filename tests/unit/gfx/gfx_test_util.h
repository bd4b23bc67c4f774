// Shared pieces of the renderer tests: one EGL context per process, settings, image access.
// The models, sprites and particles scenes are built from are in tests/scenes/scene_models.h.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "assets/model.h"
#include "gfx/particle_coverage.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "scene_models.h"

namespace arc::test {

// The process-wide headless context, or nullptr with the reason in `why`.
HeadlessContext* headless(std::string& why);

RenderSettings plain_settings();  // no near fade, full sort, given depth mode defaults
// Camera at the origin looking along −Z (fov 0.9, near 0.1), no light or ambient, starfield 7.
RenderView dark_view();
void dump_if_asked(const std::string& name, const Image& img);  // $ARCFIRE_GFX_DUMP/<name>.png
float channel(const Image& img, int x, int y, int c);  // 0..1

// The view rendered without its particles, then with them, at w×h: what the particles change.
struct ParticleFrames {
  Image background, lit;
};
ParticleFrames render_without_and_with_particles(Renderer& r, const RenderView& v, int w, int h);

// Pixels whose colour (RGB) differs between two frames of one size, and how many of those lie
// outside every rectangle (GL window pixels, y up; the images' rows run top to bottom).
struct ChangedPixels {
  int changed = 0, outside = 0;
};
ChangedPixels changed_pixels(const Image& before, const Image& after, const std::vector<PixelRect>& rects);

}  // namespace arc::test

// Skips the test, with the reason, when no EGL context can be made.
#define REQUIRE_CONTEXT()                                                    \
  do {                                                                       \
    std::string why;                                                         \
    if (!::arc::test::headless(why)) GTEST_SKIP() << "no EGL context: " << why; \
  } while (0)
