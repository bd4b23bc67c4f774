// gfx/render_settings.h — the renderer's runtime settings as it applies them (no GL).
//
// register_render_settings() defines the render.* keys (default, range and doc of each) in a
// core/settings.h Settings; Renderer::apply_settings() fills a RenderSettings from them, and
// Renderer::set_render_settings() takes one directly; both fall back where the context lacks
// a feature (reversed-Z without clip control) and clamp the ranges. The passes read it.
// A default-constructed one draws an 8-bit scene without bloom or anti-aliasing, which the
// renderer tests build on.
#pragma once

namespace arc {

class Settings;

// Defines every render.* key at its default, in `arcfire --list-settings` order.
void register_render_settings(Settings& s);

// How an HDR scene buffer is stored (RendererDesc::hdr_format); the blend reads no destination
// alpha, so three channels suffice.
enum class HdrFormat { Rgba16f, R11fG11fB10f };

struct RenderSettings {
  int soft_override = -1;  // −1: each particle's own SoftEdge; otherwise a SoftEdge value for all
  enum class Sorting { Off, Cluster, Full } sorting = Sorting::Full;
  bool reversed_z = true;
  bool infinite_far = true;
  // Sprite and model texture filtering. MipmapNearest: bilinear within the nearest mip level;
  // Mipmap: trilinear, between the two nearest levels (twice the texel reads: a clear cost
  // on a software rasteriser; docs/performance.md).
  enum class Filter { Nearest, Linear, MipmapNearest, Mipmap } filter = Filter::Mipmap;
  double scale = 1.0;
  float size_clamp = 0.5f;
  float near_fade = 2.0f;
  float contrast_power = 2.0f;
  bool sky_exact = false;    // the nebula evaluated per pixel every frame, not looked up in a baked cube map
  int sky_resolution = 256;  // texels along a face of the baked cube map (16..1024)
  int sky_grid = 0;          // baked sky looked up every N pixels and interpolated (0: every pixel; 0..64)
  // Screen layers of particle blending a frame may estimate before the nearest and largest
  // particles are shrunk, faded and dropped (overdraw_budget.h); 0: no budget.
  float overdraw_budget = 0.0f;
  float overdraw_near = 40.0f;  // m: beyond this the budget's reductions weaken with distance squared
  // Particle quads cut to where their sprite can be non-zero (sprite_trim.h). The picture is
  // the same either way; off only to measure what it saves.
  bool sprite_trim = true;
  // Soft particles read the opaque depth from the framebuffer they draw into where the driver
  // offers it (GL_ARM_shader_framebuffer_fetch_depth_stencil; llvmpipe does) instead of from a
  // copy: the same depth values and picture, no copy, and on llvmpipe a cheaper read. Off only
  // to measure what it saves, or where a driver gets it wrong.
  bool depth_fetch = true;
  // The particle batch's CPU preparation (particle_batch.h): per particle (culling, soft flags,
  // overdraw budget, runs: a software rasteriser's fill is what it saves) or per cluster stretch
  // (about a tenth of the CPU time, one draw, no budget: what a GPU wants). Auto: per cluster on
  // a hardware GPU, per particle on a software rasteriser (device_class.h).
  enum class ParticlePrep { Auto, PerParticle, PerCluster } particle_prep = ParticlePrep::Auto;
  // Depth key bits of the per-cluster full sort (ParticleBatchOptions::sort_bits): 22 orders by
  // the depth quantised to 2^22 steps over the kept range in two radix passes; 32 by the exact
  // depth in three.
  int particle_sort_bits = 22;
  int max_particle_draws = 24;  // runs the particle batch may be split into (particle_runs.h); ≥ 1
  // Particles drawn at half resolution, then put over the scene (particle_target.h): Full never,
  // Half always, Auto when a frame's particles blend more than kHalfResAbove screen layers
  // (after the budget) and again at full resolution once under kHalfResBelow (hysteresis, so a
  // frame near the line does not flicker between the two).
  enum class ParticleResolution { Full, Half, Auto } particle_resolution = ParticleResolution::Full;
  static constexpr double kHalfResAbove = 1.0, kHalfResBelow = 0.6;
  // The frame time the particle budgets follow (frame_time_target.h): frames reported over it
  // lower a level that scales overdraw_budget and the half-resolution thresholds; 0: none.
  float target_frame_ms = 0.0f;
  // HDR: a linear-light float scene, colours decoded from sRGB, one tone-map pass (post_pass.h).
  bool hdr = false;
  float exposure = 1.0f;        // scene scale before the tone curve (0.05..16)
  float bloom = 0.0f;           // strength of the glow added before tone mapping; 0 = no bloom pass
  static constexpr float kBloomLow = 0.25f, kBloomHigh = 0.5f;  // render.bloom = low / high
  enum class Antialias { Off, Fxaa, Msaa2, Msaa4 } antialias = Antialias::Off;
};

}  // namespace arc
