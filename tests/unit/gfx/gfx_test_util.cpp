// tests/unit/gfx/gfx_test_util.cpp — the EGL context, settings and image helpers of the gfx tests.
#include "gfx_test_util.h"

#include <cstdlib>

namespace arc::test {

HeadlessContext* headless(std::string& why) {
  static std::unique_ptr<HeadlessContext> ctx;
  static std::string error;
  static bool tried = false;
  if (!tried) {
    tried = true;
    try {
      ctx = create_headless_context();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  why = error;
  return ctx.get();
}

RenderView dark_view() {
  RenderView v;
  v.camera.fov_y_radians = 0.9;
  v.camera.near_plane = 0.1;
  v.light_color = glm::vec3(0);
  v.ambient = glm::vec3(0);
  v.starfield_seed = 7;
  return v;
}

RenderSettings plain_settings() {
  RenderSettings s;
  s.near_fade = 0.0f;
  return s;
}

void dump_if_asked(const std::string& name, const Image& img) {
  const char* dir = std::getenv("ARCFIRE_GFX_DUMP");
  if (dir && *dir) save_image(std::string(dir) + "/" + name + ".png", img);
}

float channel(const Image& img, int x, int y, int c) {
  return img.rgba[(size_t(y) * img.width + x) * 4 + c] / 255.0f;
}

ParticleFrames render_without_and_with_particles(Renderer& r, const RenderView& v, int w, int h) {
  RenderView empty = v;
  empty.particles.clear();
  ParticleFrames f;
  r.render(empty, w, h);
  f.background = r.read_pixels();
  r.render(v, w, h);
  f.lit = r.read_pixels();
  return f;
}

ChangedPixels changed_pixels(const Image& before, const Image& after, const std::vector<PixelRect>& rects) {
  ChangedPixels n;
  const int w = after.width, h = after.height;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t k = (size_t(h - 1 - y) * size_t(w) + size_t(x)) * 4;  // row h − 1 − y from the top
      if (after.rgba[k] == before.rgba[k] && after.rgba[k + 1] == before.rgba[k + 1] && after.rgba[k + 2] == before.rgba[k + 2])
        continue;
      ++n.changed;
      bool in = false;
      for (const PixelRect& r : rects) in = in || (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1);
      n.outside += !in;
    }
  return n;
}

}  // namespace arc::test
