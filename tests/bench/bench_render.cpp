// Renderer headline scenes through EGL at 1280×720: soft-edge cost per method, burn blending
// against plain alpha blending, and the particle pass's blended fill rate against the raw
// blended fill rate of the same context. Frame times are glFinish-bracketed averages; each
// comparison is interleaved over several rounds and the best round kept, because the machine
// is shared and noisy.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <memory>

#include <glm/gtc/quaternion.hpp>

#include "bench_registry.h"
#include "core/rng.h"
#include "gfx/renderer.h"
#include "platform/platform.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

ModelData wall(float w, float h) {
  ModelData m;
  MeshPrimitive p;
  p.positions = {{-w / 2, -h / 2, 0}, {w / 2, -h / 2, 0}, {w / 2, h / 2, 0}, {-w / 2, h / 2, 0}};
  p.normals.assign(4, glm::vec3(0, 0, 1));
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = 0;
  m.primitives.push_back(p);
  m.materials.push_back({glm::vec4(0.45f, 0.47f, 0.5f, 1), glm::vec3(0.02f), -1, -1});
  return m;
}

// Three premultiplied sprite layers: a soft puff, a hot core with a halo, a spark streak.
std::vector<Image> sprites() {
  std::vector<Image> out;
  const int n = 64;
  for (int kind = 0; kind < 3; ++kind) {
    Image img;
    img.width = img.height = n;
    img.premultiplied = true;
    img.rgba.resize(n * n * 4);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        float dx = (x + 0.5f) / n * 2 - 1, dy = (y + 0.5f) / n * 2 - 1;
        float r2 = dx * dx + dy * dy;
        float a = kind == 0 ? std::pow(std::max(0.0f, 1 - r2), 2.0f)
                  : kind == 1 ? std::min(1.0f, std::exp(-r2 * 12) + 0.4f * std::max(0.0f, 1 - r2))
                              : std::max(0.0f, 1 - std::abs(dx) * 3) * std::max(0.0f, 1 - dy * dy);
        uint8_t v = uint8_t(std::lround(std::clamp(a, 0.0f, 1.0f) * 255));
        for (int c = 0; c < 4; ++c) img.rgba[(y * n + x) * 4 + c] = v;
      }
    out.push_back(img);
  }
  return out;
}

// A gallery-like wall of effects: smoke (alpha), fire (half burn), sparks and beams (additive),
// every soft method, some particles cutting the wall and a ship-sized box.
RenderView gallery(int wall_model) {
  RenderView v;
  v.camera.position = {0, 2, 18};
  v.camera.fov_y_radians = 0.9;
  v.camera.near_plane = 0.1;
  v.meshes.push_back({wall_model, {0, 0, -6}});
  Rng rng{42, 7, 0};
  const int count = 4000;
  for (int i = 0; i < count; ++i) {
    int effect = i % 8;
    float cx = -12.0f + 3.4f * effect;
    glm::vec3 pos(cx + float(rng.range(i * 8, -1.6, 1.6)), float(rng.range(i * 8 + 1, -3.0, 6.0)),
                  -6.0f + float(rng.range(i * 8 + 2, -1.2, 3.0)));
    ParticleInstance p{};
    glm::vec3 rel = pos - glm::vec3(v.camera.position);
    p.pos[0] = rel.x;
    p.pos[1] = rel.y;
    p.pos[2] = rel.z;
    p.size = float(rng.range(i * 8 + 3, 0.25, 0.7));
    float alpha = float(rng.range(i * 8 + 4, 0.3, 0.8));
    glm::vec3 rgb = effect < 3 ? glm::vec3(0.5f, 0.5f, 0.55f) : effect < 6 ? glm::vec3(1.0f, 0.55f, 0.2f) : glm::vec3(0.6f, 0.8f, 1.0f);
    p.color[0] = rgb.r * alpha;
    p.color[1] = rgb.g * alpha;
    p.color[2] = rgb.b * alpha;
    p.color[3] = alpha;
    p.burn = effect < 3 ? 0.0f : effect < 6 ? 0.5f : 1.0f;
    p.sprite = uint16_t(effect < 3 ? 0 : effect < 6 ? 1 : 2);
    p.soft_edge = uint8_t(effect % 5);
    p.cluster = uint32_t(effect);
    if (effect >= 6) {
      p.billboard = uint8_t(Billboard::AxisLocked);
      p.axis[1] = float(rng.range(i * 8 + 5, 0.5, 1.5));
      p.axis[0] = float(rng.range(i * 8 + 6, -0.3, 0.3));
      p.size *= 0.3f;
    }
    v.particles.push_back(p);
  }
  return v;
}

double frame_ms(Renderer& r, const RenderView& v, int frames) {
  r.render(v, kWidth, kHeight);
  r.finish();
  double t0 = bench::now_seconds();
  for (int i = 0; i < frames; ++i) r.render(v, kWidth, kHeight);
  r.finish();
  return (bench::now_seconds() - t0) * 1000.0 / frames;
}

// Screen pixels covered by the particle quads (clipped to the screen), to turn time into
// blended pixels per second.
double covered_pixels(const RenderView& v) {
  double ty = std::tan(v.camera.fov_y_radians * 0.5), tx = ty * kWidth / kHeight;
  double total = 0;
  for (const ParticleInstance& p : v.particles) {
    double d = -p.pos[2];  // the camera looks down −Z with identity orientation
    if (d <= v.camera.near_plane) continue;
    double cx = p.pos[0] / (d * tx), cy = p.pos[1] / (d * ty);
    double hx = p.size / (d * tx), hy = p.size / (d * ty);
    if (p.billboard == uint8_t(Billboard::AxisLocked)) {
      double len = std::hypot(p.axis[0], p.axis[1]);
      hy = (0.5 * len + p.size) / (d * ty);
    }
    double x0 = std::max(-1.0, cx - hx), x1 = std::min(1.0, cx + hx);
    double y0 = std::max(-1.0, cy - hy), y1 = std::min(1.0, cy + hy);
    if (x1 > x0 && y1 > y0) total += (x1 - x0) * 0.5 * kWidth * (y1 - y0) * 0.5 * kHeight;
  }
  return total;
}

ARCFIRE_SCENE(render_particle_gallery) {
  std::unique_ptr<HeadlessContext> ctx;
  try {
    ctx = create_headless_context();
  } catch (const std::exception& e) {
    std::printf("skipped: no EGL context (%s)\n", e.what());
    return;
  }
  RendererDesc desc;
  desc.offscreen = true;
  Renderer r(desc);
  std::printf("context: %s\n", ctx->description().c_str());
  r.set_sprites(sprites());
  RenderView view = gallery(r.add_model(wall(60, 30)));
  RenderView no_particles = view;
  no_particles.particles.clear();
  RenderView alpha_only = view;
  for (auto& p : alpha_only.particles) p.burn = 0.0f;

  RenderSettings base;
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP")) {
    r.render(view, kWidth, kHeight);
    save_image(std::string(dir) + "/bench_gallery.png", r.read_pixels());
  }
  const int frames = 6, rounds = 3;
  const char* names[] = {"off", "linear", "contrast", "average_density", "density_extent"};
  double best[5] = {1e30, 1e30, 1e30, 1e30, 1e30};
  double burn_best = 1e30, alpha_best = 1e30, empty_best = 1e30, effect_best = 1e30;
  for (int round = 0; round < rounds; ++round) {
    for (int m = 0; m < 5; ++m) {
      RenderSettings s = base;
      s.soft_override = m;
      r.set_render_settings(s);
      best[m] = std::min(best[m], frame_ms(r, view, frames));
    }
    RenderSettings hard = base;
    hard.soft_override = 0;
    r.set_render_settings(hard);
    burn_best = std::min(burn_best, frame_ms(r, view, frames));
    alpha_best = std::min(alpha_best, frame_ms(r, alpha_only, frames));
    empty_best = std::min(empty_best, frame_ms(r, no_particles, frames));
    r.set_render_settings(base);
    effect_best = std::min(effect_best, frame_ms(r, view, frames));
  }
  double worst = 0;
  for (int m = 0; m < 5; ++m) {
    std::printf("  soft %-16s %8.2f ms/frame\n", names[m], best[m]);
    if (m > 0) worst = std::max(worst, best[m]);
  }
  std::printf("  burn blend %.2f ms, burn forced 0 %.2f ms, no particles %.2f ms, per-effect soft %.2f ms\n", burn_best,
              alpha_best, empty_best, effect_best);
  bench::report_metric("soft_edge_cost_ratio", worst / best[0]);
  bench::report_metric("burn_blend_cost_ratio", burn_best / alpha_best);

  // Raw blended fill: full-screen quads through the same context and framebuffer.
  const int quads = 40;
  double fill_best = 1e30;
  for (int round = 0; round < rounds; ++round) {
    r.render(no_particles, kWidth, kHeight);
    r.finish();
    double t0 = bench::now_seconds();
    r.draw_fill_reference(quads);
    r.finish();
    fill_best = std::min(fill_best, bench::now_seconds() - t0);
  }
  double raw_px_per_s = double(quads) * kWidth * kHeight / fill_best;
  double particle_s = std::max(1e-9, (effect_best - empty_best) * 1e-3);
  double particle_px_per_s = covered_pixels(view) / particle_s;
  // The same fill through the particle pipeline (shader, sprite array, blend): full-screen
  // particles, which separates the shader's cost from the cost of many small quads.
  RenderView big = no_particles;
  RenderSettings hard = base;
  hard.soft_override = 0;
  hard.size_clamp = 4.0f;
  r.set_render_settings(hard);
  for (int i = 0; i < quads; ++i) {
    ParticleInstance p{};
    p.pos[2] = -1.0f;
    p.size = 2.0f;
    p.color[0] = p.color[1] = p.color[2] = 0.01f;
    p.color[3] = 0.05f;
    big.particles.push_back(p);
  }
  double big_best = 1e30, big_empty = 1e30;
  for (int round = 0; round < rounds; ++round) {
    big_best = std::min(big_best, frame_ms(r, big, frames));
    big_empty = std::min(big_empty, frame_ms(r, no_particles, frames));
  }
  double big_px_per_s = double(quads) * kWidth * kHeight / std::max(1e-9, (big_best - big_empty) * 1e-3);
  std::printf("  full-screen particles through the particle pipeline: %.3g px/s\n", big_px_per_s);
  bench::report_metric("particle_shader_fill_ratio", big_px_per_s / raw_px_per_s);
  std::printf("  particle pass %.2f ms for %.0f covered pixels: %.3g px/s; raw blended fill %.3g px/s\n",
              particle_s * 1e3, covered_pixels(view), particle_px_per_s, raw_px_per_s);
  bench::report_metric("particle_fill_efficiency", particle_px_per_s / raw_px_per_s);
  bench::report_metric("render_gallery_frame_ms", effect_best);
}

}  // namespace
}  // namespace arc
