// Sprite trimming (gfx/sprite_trim.h): outside each level's box a bilinear sample of that level
// of box-filtered mipmaps is exactly zero, the boxes grow with the level, and they are tight
// (within a texel and a half of the non-zero texels); headless through EGL, trimmed quads draw
// the picture of whole ones with fewer blended pixels, under every texture filter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "assets/image.h"
#include "core/rng.h"
#include "gfx/image_compare.h"
#include "gfx/particle_batch.h"
#include "gfx/sprite_trim.h"
#include "gfx_test_util.h"
#include "core/data_root.h"

namespace arc {
namespace {

Image blank(int w, int h) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.assign(size_t(w) * size_t(h) * 4, 0);
  img.premultiplied = true;
  return img;
}

void set_texel(Image& img, int x, int y, uint8_t a) {
  uint8_t* t = &img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
  t[0] = t[1] = t[2] = uint8_t(a / 2);
  t[3] = a;
}

// Alpha of each mip level as glGenerateMipmap makes it for power-of-two sizes: each texel the
// mean of the 2 × 2 below it.
std::vector<std::vector<float>> alpha_mips(const Image& img) {
  std::vector<std::vector<float>> levels(1);
  for (size_t i = 0; i < size_t(img.width) * size_t(img.height); ++i) levels[0].push_back(float(img.rgba[i * 4 + 3]));
  for (int w = img.width, h = img.height; w > 1 || h > 1;) {
    const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
    std::vector<float> next(size_t(nw) * size_t(nh));
    const std::vector<float>& prev = levels.back();
    for (int y = 0; y < nh; ++y)
      for (int x = 0; x < nw; ++x) {
        float sum = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) sum += prev[size_t(std::min(h - 1, 2 * y + dy)) * size_t(w) + size_t(std::min(w - 1, 2 * x + dx))];
        next[size_t(y) * size_t(nw) + size_t(x)] = sum / 4.0f;
      }
    levels.push_back(std::move(next));
    w = nw, h = nh;
  }
  return levels;
}

// A bilinear, clamp-to-edge sample of a level at (u, v).
float bilinear(const std::vector<float>& level, int w, int h, float u, float v) {
  const float x = u * float(w) - 0.5f, y = v * float(h) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int xi, int yi) { return level[size_t(std::clamp(yi, 0, h - 1)) * size_t(w) + size_t(std::clamp(xi, 0, w - 1))]; };
  return (at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) + (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy;
}

TEST(SpriteTrim, MipLevelsGoDownToOneTexel) {
  EXPECT_EQ(mip_levels(1, 1), 1);
  EXPECT_EQ(mip_levels(128, 128), 8);
  EXPECT_EQ(mip_levels(128, 32), 8);
  EXPECT_EQ(mip_levels(3, 5), 3);
}

TEST(SpriteTrim, OneTexelGivesItsBilinearReachAtEachLevel) {
  Image img = blank(16, 16);
  set_texel(img, 5, 9, 200);
  const std::vector<TrimBox> b = trim_boxes({img});
  ASSERT_EQ(b.size(), 5u);
  EXPECT_FLOAT_EQ(b[0].u0, 4.5f / 16);
  EXPECT_FLOAT_EQ(b[0].u1, 6.5f / 16);
  EXPECT_FLOAT_EQ(b[0].v0, 8.5f / 16);
  EXPECT_FLOAT_EQ(b[0].v1, 10.5f / 16);
  EXPECT_FLOAT_EQ(b[1].u0, 1.5f / 8);
  EXPECT_FLOAT_EQ(b[1].u1, 3.5f / 8);  // texel (2, 4) of 8 × 8
  EXPECT_FLOAT_EQ(b[4].u0, 0.0f);
  EXPECT_FLOAT_EQ(b[4].u1, 1.0f);          // the 1 × 1 level: everywhere
}

TEST(SpriteTrim, AnEmptySpriteHasAnEmptyBox) {
  const std::vector<TrimBox> b = trim_boxes({blank(8, 8)});
  for (const TrimBox& t : b) EXPECT_TRUE(t.u0 == t.u1 && t.v0 == t.v1);
}

TEST(SpriteTrim, ASmallerLayerIsTrimmedAsTheArrayStretchesIt) {
  Image small = blank(4, 4);
  set_texel(small, 3, 0, 255);
  const Image big = stretch_nearest(small, 16, 16);
  ASSERT_EQ(big.width, 16);
  const std::vector<TrimBox> b = trim_boxes({big});
  EXPECT_FLOAT_EQ(b[0].u0, 11.5f / 16);
  EXPECT_FLOAT_EQ(b[0].v1, 4.5f / 16);
}

// The depth D a quad's level is taken at: a camera-facing quad's view depth, a segment's
// R + radius²/R; the level: log2(lod_scale · D / size) rounded (nearest) or the next level up
// (trilinear), level 0 without mipmaps, within the texture's levels.
TEST(SpriteTrim, LevelFollowsTheBoundAndTheFilter) {
  EXPECT_FLOAT_EQ(SpriteTrim::facing_depth(16.0f, 0.1f), 16.0f);
  EXPECT_FLOAT_EQ(SpriteTrim::facing_depth(0.01f, 0.1f), 0.1f);
  EXPECT_FLOAT_EQ(SpriteTrim::segment_depth(16.0f, 1.0f, 1.0f, 0.1f), 16.125f);
  // A segment larger than its distance counts as much farther than its centre (2 + 32/2).
  EXPECT_FLOAT_EQ(SpriteTrim::segment_depth(2.0f, 4.0f, 4.0f, 0.1f), 18.0f);
  EXPECT_FLOAT_EQ(SpriteTrim::segment_depth(0.0f, 1.0f, 1.0f, 4.0f), SpriteTrim::segment_depth(4.0f, 1.0f, 1.0f, 4.0f));
  // lod_scale 1, size 1, D 16.125: lod 4.011.
  EXPECT_EQ(SpriteTrim::level(TrimMode::NearestLevel, 1.0f, 1.0f, 16.125f, 8), 4);
  EXPECT_EQ(SpriteTrim::level(TrimMode::Trilinear, 1.0f, 1.0f, 16.125f, 8), 5);
  EXPECT_EQ(SpriteTrim::level(TrimMode::BaseLevel, 1.0f, 1.0f, 16.125f, 8), 0);
  EXPECT_EQ(SpriteTrim::level(TrimMode::Off, 1.0f, 1.0f, 16.125f, 8), 0);
  // Rounding to the nearest level goes up from lod 4.45 (4.5 less the 0.05 allowed for rounding).
  EXPECT_EQ(SpriteTrim::level(TrimMode::NearestLevel, std::exp2(4.44f) / 16.0f, 1.0f, 16.0f, 8), 4);
  EXPECT_EQ(SpriteTrim::level(TrimMode::NearestLevel, std::exp2(4.46f) / 16.0f, 1.0f, 16.0f, 8), 5);
  // Far ones stop at the 1 × 1 level, huge near ones at level 0.
  EXPECT_EQ(SpriteTrim::level(TrimMode::Trilinear, 1.0f, 0.01f, 1e6f, 8), 7);
  EXPECT_EQ(SpriteTrim::level(TrimMode::NearestLevel, 0.01f, 50.0f, 60.0f, 8), 0);
  // A sprite the boxes do not cover, or trimming off, keeps the whole quad.
  SpriteTrim t;
  t.boxes = trim_boxes({blank(8, 8)});
  t.levels = 4;
  const TrimBox whole = t.box(TrimMode::NearestLevel, 3, 1.0f, 1.0f, 10.0f);
  EXPECT_EQ(whole.u0, 0.0f);
  EXPECT_EQ(whole.u1, 1.0f);
  EXPECT_EQ(t.box(TrimMode::Off, 0, 1.0f, 1.0f, 10.0f).v1, 1.0f);
  EXPECT_EQ(t.box(TrimMode::NearestLevel, 0, 1.0f, 1.0f, 10.0f).u0, 0.5f);  // the empty sprite's box
}

// Random sparse sprites: every sample outside a level's box is exactly zero, a coarser level's
// box holds a finer one's, and each box reaches at most 1.5 texels past the non-zero texels of
// its level.
TEST(SpriteTrim, SamplesOutsideTheBoxAreZeroAndTheBoxIsTight) {
  const Rng rng{11, 3, 0};
  for (uint64_t k = 0; k < 40; ++k) {
    Image img = blank(32, 32);
    const int cx = int(rng.range(k * 8, 4, 28)), cy = int(rng.range(k * 8 + 1, 4, 28));
    const int rx = int(rng.range(k * 8 + 2, 0, 6)), ry = int(rng.range(k * 8 + 3, 0, 6));
    for (int y = std::max(0, cy - ry); y <= std::min(31, cy + ry); ++y)
      for (int x = std::max(0, cx - rx); x <= std::min(31, cx + rx); ++x)
        if (rng.uniform(k * 4096 + uint64_t(y * 32 + x)) < 0.5) set_texel(img, x, y, uint8_t(1 + (x * 7 + y) % 250));
    set_texel(img, cx, cy, 9);
    const std::vector<TrimBox> boxes = trim_boxes({img});
    const std::vector<std::vector<float>> mips = alpha_mips(img);
    ASSERT_EQ(boxes.size(), mips.size());
    for (size_t m = 0; m < mips.size(); ++m) {
      const int n = std::max(1, 32 >> m);
      const TrimBox& b = boxes[m];
      if (m > 0) {
        EXPECT_LE(b.u0, boxes[m - 1].u0);
  EXPECT_GE(b.u1, boxes[m - 1].u1);
        EXPECT_LE(b.v0, boxes[m - 1].v0);
  EXPECT_GE(b.v1, boxes[m - 1].v1);
      }
      int lo = n, hi = -1;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          if (mips[m][size_t(y) * size_t(n) + size_t(x)] > 0) lo = std::min(lo, x), hi = std::max(hi, x);
      ASSERT_GE(hi, 0);
      EXPECT_GE(b.u0, std::max(0.0f, (float(lo) - 0.5f) / float(n)) - 1e-6f) << "sprite " << k << " level " << m;
      EXPECT_LE(b.u1, std::min(1.0f, (float(hi) + 1.5f) / float(n)) + 1e-6f) << "sprite " << k << " level " << m;
      for (int s = 0; s < 400; ++s) {
        const float u = float(rng.uniform(k * 100000 + m * 1000 + uint64_t(s) * 2));
        const float v = float(rng.uniform(k * 100000 + m * 1000 + uint64_t(s) * 2 + 1));
        if (u >= b.u0 && u <= b.u1 && v >= b.v0 && v <= b.v1) continue;
        ASSERT_EQ(bilinear(mips[m], n, n, u, v), 0.0f) << "sprite " << k << " level " << m << " at " << u << ", " << v;
      }
    }
  }
}

// Big and small particles of every sprite, near and far, camera-facing (turned) and axis-locked
// streaks, some larger than their distance from the eye: trimmed quads blend fewer pixels and
// draw the same picture as whole ones.
TEST(SpriteTrim, TrimmedQuadsDrawTheWholeQuadsPicture) {
  REQUIRE_CONTEXT();
  Renderer r(RendererDesc{.offscreen = true});
  std::vector<Image> sprites;
  for (const char* name : {"blob", "glow", "spark", "flare", "smoke", "shield"})
    sprites.push_back(load_sprite(arc::data_root() + "/assets/textures/sprite_" + name + ".png"));
  r.set_sprites(sprites);
  RenderView v = test::dark_view();
  for (int i = 0; i < 90; ++i) {
    const float depth = 3.0f + 2.5f * float(i % 9);
    ParticleInstance p = scenes::particle({-6.0f + 0.14f * float(i), float(i % 5) - 2.0f, -depth}, 0.2f + 0.12f * float(i % 7),
                                          glm::vec3(0.9f, 0.6f, 0.3f), 0.6f, i % 2 ? 1.0f : 0.0f, SoftEdge::Off);
    p.sprite = uint8_t(i % 6);
    p.rotation = 0.37f * float(i);
    if (i % 6 == 2) {
      p.billboard = uint8_t(Billboard::AxisLocked);
      p.axis[0] = 0.8f * std::cos(0.5f * float(i)), p.axis[1] = 1.5f * std::sin(0.5f * float(i)), p.axis[2] = -0.7f;
      p.size *= 0.3f;
    }
    v.particles.push_back(p);
  }
  // Quads larger than their distance, off the view axis: their far corners show smaller than
  // their centre, the case the level's bound (R + radius²/R) is for.
  for (int i = 0; i < 12; ++i) {
    const float a = 0.52f * float(i);
    ParticleInstance p = scenes::particle({1.6f * std::cos(a), 0.9f * std::sin(a), -1.5f - 0.25f * float(i)}, 1.2f + 0.15f * float(i),
                                          glm::vec3(0.3f, 0.5f, 0.9f), 0.25f, 1.0f, SoftEdge::Off);
    p.sprite = uint8_t(i % 6);
    p.rotation = 0.8f * float(i);
    v.particles.push_back(p);
  }
  for (auto filter : {RenderSettings::Filter::MipmapNearest, RenderSettings::Filter::Mipmap, RenderSettings::Filter::Linear}) {
    RenderSettings s = test::plain_settings();
    s.filter = filter;
    s.sprite_trim = false;
    r.set_render_settings(s);
    r.count_particle_fragments(true);
    r.render(v, 480, 270);
    const Image whole = r.read_pixels();
    const long long whole_px = r.last_stats().particle_fragments;
    const double whole_estimate = r.last_stats().overdraw_estimated_layers * 480 * 270;
    s.sprite_trim = true;
    r.set_render_settings(s);
    r.render(v, 480, 270);
    const Image trimmed = r.read_pixels();
    const long long trimmed_px = r.last_stats().particle_fragments;
    const double trimmed_estimate = r.last_stats().overdraw_estimated_layers * 480 * 270;
    // The budget's estimate follows the trimmed quads (within the rounding of edges to pixels).
    EXPECT_NEAR(whole_estimate / double(whole_px), 1.0, 0.1) << "filter " << int(filter);
    EXPECT_NEAR(trimmed_estimate / double(trimmed_px), 1.0, 0.1) << "filter " << int(filter);
    test::dump_if_asked("sprite_trim_" + std::to_string(int(filter)), trimmed);
    EXPECT_LT(double(trimmed_px), 0.9 * double(whole_px)) << "filter " << int(filter);
    // The same texels at the same pixels; only the interpolated texture coordinate may round
    // differently in its last bit (measured: 0.02–0.03 % of pixels 1/255 apart, 88–89 dB). A
    // level a little too fine (D × 0.6) cuts off the faint rim a coarser level spreads: 0.06–0.1 %
    // of pixels, up to 2/255.
    const ImageDiff d = compare_images(whole, trimmed, ImageCompareRule{0, 0.0});
    EXPECT_LE(d.max_diff, 1) << "filter " << int(filter);
    EXPECT_GE(d.fraction_within, 0.9995) << "filter " << int(filter);
    EXPECT_GE(psnr_db(whole, trimmed), 80.0) << "filter " << int(filter);
  }
}

// The tiles the half-resolution composite, the runs and the depth copy use are the trimmed
// quads' boxes (a reduced particle keeps its whole quad's): every pixel the particles change
// lies in them, and they cover less than the whole quads' boxes.
TEST(SpriteTrim, TrimmedBoxesHoldEveryLitPixel) {
  REQUIRE_CONTEXT();
  std::vector<Image> sprites;
  for (const char* name : {"blob", "glow", "spark", "flare", "smoke", "shield"})
    sprites.push_back(load_sprite(arc::data_root() + "/assets/textures/sprite_" + name + ".png"));
  Renderer r(RendererDesc{.offscreen = true});
  r.set_sprites(sprites);
  RenderView v = test::dark_view();
  v.starfield_seed = 0;
  const Rng rng{5, 9, 0};
  for (int i = 0; i < 48; ++i) {
    const glm::vec3 pos(float(rng.uniform(uint64_t(i) * 5) * 16.0 - 8.0), float(rng.uniform(uint64_t(i) * 5 + 1) * 9.0 - 4.5),
                        -float(2.0 + rng.uniform(uint64_t(i) * 5 + 2) * 18.0));
    ParticleInstance p = scenes::particle(pos, 0.6f, glm::vec3(1.0f, 0.8f, 0.5f), 1.0f, 1.0f, SoftEdge::Off);
    p.sprite = uint8_t(i % 6);
    p.rotation = float(rng.uniform(uint64_t(i) * 5 + 3) * 6.283);
    if (i % 6 == 2) {
      p.billboard = uint8_t(Billboard::AxisLocked);
      const float t = float(rng.uniform(uint64_t(i) * 5 + 4) * 6.283);
      p.axis[0] = 6.0f * std::cos(t), p.axis[1] = 3.6f * std::sin(t), p.axis[2] = 2.5f;
      p.size = 0.2f;
    }
    v.particles.push_back(p);
  }
  const int w = 320, h = 180;
  for (auto filter : {RenderSettings::Filter::MipmapNearest, RenderSettings::Filter::Mipmap}) {
    RenderSettings s = test::plain_settings();
    s.filter = filter;
    s.particle_resolution = RenderSettings::ParticleResolution::Full;
    r.set_render_settings(s);
    const auto [background, lit] = test::render_without_and_with_particles(r, v, w, h);
    SpriteTrim trim;
    trim.boxes = trim_boxes(sprites);
    trim.levels = mip_levels(sprites[0].width, sprites[0].height);
    trim.texels = sprites[0].width;
    ParticleBatchOptions o;
    o.width = w, o.height = h, o.size_clamp = s.size_clamp;
    o.trim = &trim;
    o.trim_height = h;
    const ViewProjection vp = make_view_projection(v.camera, double(w) / double(h), s.reversed_z, s.infinite_far);
    ParticleBatch whole, trimmed;
    whole.prepare(v, vp, {}, o);
    o.trim_mode = trim_mode(s);
    trimmed.prepare(v, vp, {}, o);
    std::vector<PixelRect> rects;
    trimmed.coverage.rects(rects);
    const test::ChangedPixels px = test::changed_pixels(background, lit, rects);
    EXPECT_GT(px.changed, 2000) << "filter " << int(filter);
    EXPECT_EQ(px.outside, 0) << "filter " << int(filter);
    EXPECT_LT(trimmed.coverage.share(), whole.coverage.share()) << "filter " << int(filter);
  }
}

}  // namespace
}  // namespace arc
