// gfx/renderer.cpp — the frame: which pass runs when, on what the previous one wrote.
//
// Frame graph (render()). Each pass owns its GL objects; the render targets are the edges:
//
//   pass            reads                                  writes
//   ─────────────── ────────────────────────────────────── ─────────────────────────────────
//   nebula          view seed, camera; baked nebula cube   opaque colour (depth off; an 8-bit
//                   (corner texture: 8-bit scene, grid)    scene: its colour-only framebuffer)
//   clear           —                                      depth = far (the colour is the sky's)
//   stars           view seed, camera                      opaque colour (blended, depth off)
//   mesh (opaque)   view meshes, model GPU buffers         opaque colour + depth
//   MSAA resolve    opaque target (msaa2/msaa4 only)       scene colour (averaged) + scene depth
//                                                          (one sample)
//   particle batch  view particles, mesh cover boxes (CPU) upload list, soft flags, order
//   depth copy      scene depth (only if a drawn particle  depth-copy texture
//                   is soft and a mesh is within reach)
//   particles       upload list, sprites, depth copy       scene colour (blended, depth test on,
//                                                          depth write off)
//   bloom (HDR)     scene colour                           bloom chain (half size and down)
//   post            scene colour, bloom chain              output: window or offscreen target
//                                                          (tone map and/or FXAA, or a blit)
//   HUD             view HUD layer, font atlas             output (full size, alpha-blended)
//   read-back       output (offscreen) or scene colour     Image / float pixels, on request
//
// The opaque target is the scene buffer itself without MSAA. With render.hdr the scene colour is
// a float buffer in linear light (colours decoded from sRGB as they enter), tone-mapped once by
// the post pass; without it the scene is 8-bit display values, drawn directly. GPU timers bracket
// the depth copy + particles.
//
// Row order. In a window whose post pass is a plain resolve (8-bit scene, no FXAA or MSAA) the
// scene is stored top row first, as the window system stores the window (RendererDesc::
// top_down_scene): sky, meshes and particles draw with clip control's upper-left origin,
// the rectangles of the depth copy and of the half-resolution composite (counted from the
// bottom, as the particle batch computes them) are turned into stored rows, the sky's cube map
// is baked lower-left as always, and the resolve reads the rows reversed, which Mesa then does
// as a copy. The post pass and the HUD draw lower-left into the output.
#include "gfx/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "gfx/bloom_pass.h"
#include "gfx/device_class.h"
#include "gfx/frame_time_target.h"
#include "gfx/gl_features.h"
#include "gfx/gpu_timers.h"
#include "gfx/hud_pass.h"
#include "gfx/mesh_pass.h"
#include "gfx/particle_batch.h"
#include "gfx/particle_pass.h"
#include "gfx/particle_target.h"
#include "gfx/post_pass.h"
#include "gfx/render_targets.h"
#include "gfx/shader_programs.h"
#include "gfx/sky_pass.h"
#include "gfx/view_projection.h"

namespace arc {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string describe_context() {
  std::string version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return version + " (" + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ")";
}

}  // namespace

struct Renderer::Impl {
  explicit Impl(const RendererDesc& d)
      : desc(d),
        version(describe_context()),
        clip_control(arc::has_clip_control()),
        software(is_software_rasteriser(reinterpret_cast<const char*>(glGetString(GL_RENDERER)))),
        programs(d.shader_dir),
        targets(d.offscreen, d.float_scene),
        particles(d.max_particles_per_draw) {}

  RendererDesc desc;
  RenderSettings rs;
  std::string version;
  bool clip_control;
  bool software;  // GL_RENDERER names a software rasteriser (device_class.h)

  ShaderPrograms programs;
  RenderTargets targets;
  SkyPass sky;
  MeshPass meshes;
  ParticleBatch batch;  // CPU only, kept for its buffers
  FrameTimeTarget frame_target;  // the level the particle budgets follow (render.target_frame_ms)
  ParticlePass particles;
  ParticleTarget half_particles;
  std::vector<PixelRect> composite_rects;  // where the half-resolution target is put over the scene
  std::vector<PixelRect> depth_rects;      // where the depth copy is filled (the soft particles' tiles)
  bool half_res = false;  // this frame's particles at half resolution (kept between frames for Auto's hysteresis)
  // The states particle variants were compiled for (warm_up_particles): scene format, depth
  // direction, sprite filter and contrast program, packed as warm_key() makes them.
  std::vector<uint64_t> warm_keys;
  uint64_t warm_key() const;
  // Soft particles read the depth of the framebuffer they draw into (RenderSettings::depth_fetch).
  bool depth_fetch_usable() const { return rs.depth_fetch && has_depth_fetch(); }
  // The particle batch is prepared per cluster (render.particle_prep; auto: not on a software
  // rasteriser), and so drawn by the INDEXED programs, built the first time this holds.
  bool by_cluster() const;
  void ensure_indexed_programs();
  ParticleBatchOptions batch_options() const;
  BloomPass bloom;
  PostPass post;
  HudPass hud;
  GpuTimers timers;
  FrameStats stats;

  SceneFormat scene_format() const;
  void set_origin(bool upper_left) const;
  void clear_scene();
  void draw_particles(const RenderView& v, const ViewProjection& vp);
  void warm_up_particles(const RenderView& v, const ViewProjection& vp);
  void begin_half_resolution(ParticleFrame& frame);
  void post_process(int width, int height);
};

std::string describe_particle_stats(const FrameStats& s) {
  char line[160];
  std::snprintf(line, sizeof line, "particles %d, %d reduced | %d draws | %.1f screens blended (%.1f before the budget)",
                s.particles_drawn, s.particles_reduced, s.particle_draw_calls, s.overdraw_budgeted_layers,
                s.overdraw_estimated_layers);
  return line;
}

Renderer::Renderer(const RendererDesc& desc) {
  int ver = epoxy_gl_version();
  if (ver < 33) throw std::runtime_error("OpenGL 3.3 or newer is needed, the context has " + std::to_string(ver / 10) + "." + std::to_string(ver % 10));
  impl_ = std::make_unique<Impl>(desc);
}

Renderer::~Renderer() = default;

std::string Renderer::gl_version() const { return impl_->version; }
std::string Renderer::gl_renderer() const {
  const GLubyte* name = glGetString(GL_RENDERER);
  return name ? reinterpret_cast<const char*>(name) : "";
}
bool Renderer::has_clip_control() const { return impl_->clip_control; }

ModelId Renderer::add_model(const ModelData& model) {
  return ModelId::from_index(size_t(impl_->meshes.add_model(model, impl_->rs.filter)));
}

void Renderer::set_sprites(const std::vector<Image>& sprites) { impl_->particles.set_sprites(sprites, impl_->rs.filter); }

void Renderer::apply_settings(const Settings& s) {
  RenderSettings r;
  const std::string& soft = s.choice("render.soft_edges");
  const char* names[] = {"off", "linear", "contrast", "average_density", "density_extent"};
  r.soft_override = -1;
  for (int i = 0; i < 5; ++i)
    if (soft == names[i]) r.soft_override = i;
  const std::string& sorting = s.choice("render.sorting");
  r.sorting = sorting == "off" ? RenderSettings::Sorting::Off
              : sorting == "cluster" ? RenderSettings::Sorting::Cluster
                                     : RenderSettings::Sorting::Full;
  const std::string& prep = s.choice("render.particle_prep");
  r.particle_prep = prep == "particle"  ? RenderSettings::ParticlePrep::PerParticle
                    : prep == "cluster" ? RenderSettings::ParticlePrep::PerCluster
                                        : RenderSettings::ParticlePrep::Auto;
  r.particle_sort_bits = std::stoi(s.choice("render.particle_sort_bits"));
  r.reversed_z = s.choice("render.depth_mode") == "reversed";
  r.infinite_far = s.flag("render.infinite_far");
  const std::string& f = s.choice("render.texture_filter");
  r.filter = f == "nearest"          ? RenderSettings::Filter::Nearest
             : f == "linear"         ? RenderSettings::Filter::Linear
             : f == "mipmap_nearest" ? RenderSettings::Filter::MipmapNearest
                                     : RenderSettings::Filter::Mipmap;
  r.scale = s.number("render.scale");
  r.size_clamp = float(s.number("render.particle_size_clamp"));
  r.near_fade = float(s.number("render.near_fade"));
  r.contrast_power = float(s.number("render.contrast_power"));
  r.sky_exact = s.choice("render.sky") == "exact";
  r.sky_resolution = int(s.integer("render.sky_resolution"));
  r.sky_grid = int(s.integer("render.sky_grid"));
  r.overdraw_budget = float(s.number("render.overdraw_budget"));
  r.overdraw_near = float(s.number("render.overdraw_near"));
  r.target_frame_ms = float(s.number("render.target_frame_ms"));
  const std::string& pr = s.choice("render.particle_resolution");
  r.particle_resolution = pr == "half"   ? RenderSettings::ParticleResolution::Half
                          : pr == "auto" ? RenderSettings::ParticleResolution::Auto
                                         : RenderSettings::ParticleResolution::Full;
  r.hdr = s.flag("render.hdr");
  r.exposure = float(s.number("render.exposure"));
  const std::string& bloom = s.choice("render.bloom");
  r.bloom = bloom == "high" ? RenderSettings::kBloomHigh : bloom == "low" ? RenderSettings::kBloomLow : 0.0f;
  const std::string& aa = s.choice("render.antialias");
  r.antialias = aa == "fxaa"    ? RenderSettings::Antialias::Fxaa
                : aa == "msaa2" ? RenderSettings::Antialias::Msaa2
                : aa == "msaa4" ? RenderSettings::Antialias::Msaa4
                                : RenderSettings::Antialias::Off;
  set_render_settings(r);
}

void Renderer::set_render_settings(const RenderSettings& s) {
  Impl& m = *impl_;
  m.rs = s;
  if (!m.clip_control) m.rs.reversed_z = false;
  m.rs.scale = std::clamp(m.rs.scale, 0.1, 4.0);
  m.rs.sky_resolution = std::clamp(m.rs.sky_resolution, 16, 1024);
  m.rs.sky_grid = std::clamp(m.rs.sky_grid, 0, 64);
  m.rs.exposure = std::clamp(m.rs.exposure, 0.05f, 16.0f);
  m.rs.bloom = std::clamp(m.rs.bloom, 0.0f, 4.0f);
  m.particles.set_texture_filter(m.rs.filter);
  m.meshes.set_texture_filter(m.rs.filter);
  m.frame_target.set_target(m.rs.target_frame_ms);
  m.ensure_indexed_programs();
}

const RenderSettings& Renderer::render_settings() const { return impl_->rs; }

void Renderer::render(const RenderView& v, int width, int height) {
  Impl& m = *impl_;
  if (width <= 0 || height <= 0) throw std::invalid_argument("render: width and height must be positive");
  m.stats = FrameStats{};
  m.stats.frame_level = m.frame_target.level();
  m.particles.forget_fragments();  // an earlier frame's count nobody asked for
  m.timers.collect_finished();
  m.targets.ensure(width, height, m.rs.scale, m.scene_format());
  const int scene_w = m.targets.scene_width(), scene_h = m.targets.scene_height();
  const ViewProjection vp =
      make_view_projection(v.camera, double(scene_w) / double(scene_h), m.rs.reversed_z, m.rs.infinite_far);

  m.ensure_indexed_programs();
  if (std::find(m.warm_keys.begin(), m.warm_keys.end(), m.warm_key()) == m.warm_keys.end()) m.warm_up_particles(v, vp);
  auto t = std::chrono::steady_clock::now();
  // The nebula first (an 8-bit BGRA scene takes it into its colour alone: gfx/sky_pass.h),
  // then the depth cleared with the stars and meshes, in the opaque target.
  m.set_origin(m.targets.top_down());
  m.targets.bind_opaque();
  const GLuint sky_fbo = m.targets.scene_bgra() ? m.targets.scene_color_fbo() : 0;
  m.stats.draw_calls += m.sky.draw_nebula(v, m.programs, vp, m.rs, scene_w, scene_h, sky_fbo);
  m.clear_scene();
  m.stats.draw_calls += m.sky.draw_stars(v, m.programs, vp, m.rs, scene_h);
  m.stats.draw_calls += m.meshes.draw(v, m.programs.mesh, vp.view_proj, m.rs.reversed_z, m.rs.hdr);
  m.targets.resolve_opaque(m.programs.msaa_resolve);
  m.stats.msaa_samples = m.targets.samples();
  m.stats.opaque_cpu_ms = ms_since(t);
  m.draw_particles(v, vp);
  m.set_origin(false);  // the post pass and the HUD draw into the output as GL stores it
  t = std::chrono::steady_clock::now();
  m.post_process(width, height);
  m.stats.post_cpu_ms = ms_since(t);
  t = std::chrono::steady_clock::now();
  m.stats.draw_calls += m.hud.draw(v.hud, m.programs.hud, width, height);
  m.stats.hud_cpu_ms = ms_since(t);
  m.stats.particle_gpu_ms = m.timers.last_particle_gpu_ms();
}

void Renderer::restart_smoothing() { impl_->batch.restart_smoothing(); }

void Renderer::report_frame_time(double ms) {
  const FrameStats& s = impl_->stats;
  impl_->frame_target.observe(ms, s.particles_reduced > 0 || s.particles_half_res);
}

double Renderer::frame_level() const { return impl_->frame_target.level(); }

bool Renderer::warm_sky(uint64_t starfield_seed) { return impl_->sky.warm(starfield_seed, impl_->programs, impl_->rs); }

SceneFormat Renderer::Impl::scene_format() const {
  SceneFormat f;
  f.hdr = rs.hdr;
  f.hdr_format = desc.hdr_format;
  f.samples = rs.antialias == RenderSettings::Antialias::Msaa4   ? 4
              : rs.antialias == RenderSettings::Antialias::Msaa2 ? 2
                                                                  : 0;
  using TopDown = RendererDesc::TopDownScene;
  const bool wanted = desc.top_down_scene == TopDown::On || (desc.top_down_scene == TopDown::Auto && !desc.offscreen);
  f.top_down = wanted && clip_control && !rs.hdr && !desc.float_scene && rs.antialias == RenderSettings::Antialias::Off;
  return f;
}

// Clip control's origin: upper left draws the scene top row first (a top-down scene), lower
// left as GL stores a framebuffer. The depth mode follows render.depth_mode either way.
void Renderer::Impl::set_origin(bool upper_left) const {
  if (clip_control)
    glClipControl(upper_left ? GL_UPPER_LEFT : GL_LOWER_LEFT, rs.reversed_z ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
}

void Renderer::Impl::clear_scene() {
  targets.bind_opaque();
  glDepthMask(GL_TRUE);
  glClearDepth(rs.reversed_z ? 0.0 : 1.0);
  // Depth only: the nebula has written every pixel's colour and an alpha of 1, so clearing the
  // colour too would fill the frame twice, a cost a software rasteriser feels.
  glClear(GL_DEPTH_BUFFER_BIT);
}

// What the particle batch is prepared with this frame: the settings, the draw limit, and the
// target's size and level of detail.
ParticleBatchOptions Renderer::Impl::batch_options() const {
  ParticleBatchOptions options;
  options.soft_override = rs.soft_override;
  options.sorting = rs.sorting;
  options.max_particles = particles.max_particles_per_draw();
  options.max_source = particles.max_source_particles();
  options.sort_bits = rs.particle_sort_bits;
  options.by_cluster = by_cluster();
  options.overdraw = {rs.overdraw_budget * float(frame_target.level()), rs.overdraw_near,
                      float(frame_target.min_px(targets.scene_height()))};
  options.size_clamp = rs.size_clamp;
  options.max_runs = std::max(1, rs.max_particle_draws);
  options.depth_tiles = !depth_fetch_usable();
  options.trim = &particles.trim();
  options.trim_mode = trim_mode(rs);
  // The sampler's level of detail follows the target: the half-resolution one when it is set
  // or was chosen last frame (the choice for this one follows from the estimate).
  using Res = RenderSettings::ParticleResolution;
  const bool likely_half = rs.particle_resolution == Res::Half || (rs.particle_resolution == Res::Auto && half_res);
  options.trim_height = likely_half ? std::max(1, targets.scene_height() / 2) : targets.scene_height();
  // Layers are shares of the screen whichever target the particles blend into.
  options.width = targets.scene_width();
  options.height = targets.scene_height();
  return options;
}

// The CPU batch (no GL), then upload, the depth copy when a drawn particle is soft and the
// depth cannot be fetched, and the runs' draws; particle_prep_ms covers the batch,
// particle_cpu_ms all of it.
void Renderer::Impl::draw_particles(const RenderView& v, const ViewProjection& vp) {
  const auto t0 = std::chrono::steady_clock::now();
  stats.particles_in = int(v.particles.size());
  batch.prepare(v, vp, meshes.cover_boxes(), batch_options());
  stats.particles_drawn = batch.visible;
  stats.overdraw_estimated_layers = batch.overdraw.estimated_layers;
  stats.overdraw_budgeted_layers = batch.overdraw.budgeted_layers;
  stats.particles_reduced = batch.overdraw.reduced;
  stats.particles_dropped = batch.overdraw.dropped;
  stats.overdraw_cap = batch.overdraw.cap;
  stats.culled_offscreen = batch.culled_offscreen;
  stats.over_draw_limit = batch.over_draw_limit;
  stats.sorted = batch.sorted;
  stats.soft_shaded = batch.soft_shaded;
  stats.particle_prep_ms = ms_since(t0);
  using Res = RenderSettings::ParticleResolution;
  const double level = frame_target.level();  // late frames go to half resolution at fewer layers
  if (rs.particle_resolution != Res::Auto) half_res = rs.particle_resolution == Res::Half;
  else if (batch.overdraw.budgeted_layers > RenderSettings::kHalfResAbove * level) half_res = true;
  else if (batch.overdraw.budgeted_layers < RenderSettings::kHalfResBelow * level) half_res = false;
  stats.particles_half_res = half_res;
  if (batch.drawn() == 0) {
    stats.particle_cpu_ms = stats.particle_prep_ms;
    return;
  }
  particles.upload(batch);
  timers.begin_particle_pass();
  // Soft edges read this frame's opaque depth. Where the driver lets a fragment read the depth
  // of the framebuffer it draws into, they read that: the scene's depth at full resolution, the
  // half target's (taken from the scene's) at half. Otherwise particles drawn at full
  // resolution test against the scene's depth buffer, so they read a copy; at half resolution
  // they test against the half target's own depth and read the scene's depth texture as it is.
  auto t = std::chrono::steady_clock::now();
  const bool fetch = depth_fetch_usable();
  stats.depth_fetched = batch.any_soft && fetch;
  if (batch.any_soft && !half_res && !fetch) {
    batch.depth_reads.rects(depth_rects);
    if (targets.top_down()) flip_rows(depth_rects, targets.scene_height());
    targets.copy_depth(depth_rects);
    stats.depth_copied = true;
  }
  ParticleFrame frame{vp, v.camera.fov_y_radians, float(v.camera.near_plane),
                      half_res ? targets.scene_depth() : targets.depth_copy(), targets.scene_width(),
                      targets.scene_height()};
  frame.depth_fetch = fetch;
  if (half_res) begin_half_resolution(frame);
  if (half_res || stats.depth_copied) stats.particle_target_cpu_ms = ms_since(t);
  stats.particle_target_pixels = double(frame.scene_width) * double(frame.scene_height);
  int draws = particles.draw(batch, programs, rs, frame);
  if (half_res) {
    t = std::chrono::steady_clock::now();
    batch.coverage.rects(composite_rects);
    // The composite maps its rectangles to rows of the target as they are stored (lower-left
    // origin), and both the scene and the half-resolution target are top-down when the scene is.
    if (targets.top_down()) {
      flip_rows(composite_rects, targets.scene_height());
      set_origin(false);
    }
    half_particles.composite(programs.particle_composite, targets.scene_color_fbo(), targets.scene_width(),
                             targets.scene_height(), composite_rects);
    targets.bind_scene();
    stats.composite_share = batch.coverage.share();
    stats.particle_composite_cpu_ms = ms_since(t);
    ++draws;
  }
  stats.draw_calls += draws;
  stats.particle_draw_calls += draws;
  stats.particle_pass_gpu_ms = timers.end_particle_pass();
  stats.particle_cpu_ms = ms_since(t0);
}

// The half-resolution target bound, holding the scene's depth, and `frame` made to draw into it.
void Renderer::Impl::begin_half_resolution(ParticleFrame& frame) {
  half_particles.begin(targets.scene_fbo(), targets.scene_width(), targets.scene_height(), targets.scene_internal_format());
  frame.scene_width = half_particles.width();
  frame.scene_height = half_particles.height();
  frame.transmittance_alpha = true;
}

bool Renderer::Impl::by_cluster() const {
  using Prep = RenderSettings::ParticlePrep;
  return rs.particle_prep == Prep::PerCluster || (rs.particle_prep == Prep::Auto && !software);
}

void Renderer::Impl::ensure_indexed_programs() {
  if (by_cluster() && !programs.has_indexed()) programs.build_indexed();
}

uint64_t Renderer::Impl::warm_key() const {
  const uint64_t contrast = rs.contrast_power == 2.0f ? 0 : rs.contrast_power == 1.0f ? 1 : 2;
  return uint64_t(targets.scene_internal_format()) << 16 | uint64_t(by_cluster()) << 14 |
         uint64_t(depth_fetch_usable()) << 12 |
         uint64_t(rs.reversed_z) << 8 | uint64_t(rs.filter) << 4 | uint64_t(rs.hdr) << 2 | contrast;
}

// A driver compiles a program's variant for each blend, depth and framebuffer state the first
// time it draws with it: on llvmpipe that compile is a visible hitch the first time a battle's
// particles go to half resolution or a soft run appears. So the first frame in each state the
// variants depend on (scene format, depth direction, sprite filter, HDR, contrast program:
// warm_key), before it clears the scene, one tiny particle per program (hard, linear, the
// contrast curve, density extent, both) is drawn into the scene and into the half-resolution
// target, and that is put over the scene: every variant the frames can pick is compiled there,
// by the INDEXED programs too when the batch is prepared per cluster. The frame's sky then
// covers it all.
void Renderer::Impl::warm_up_particles(const RenderView& v, const ViewProjection& vp) {
  warm_keys.push_back(warm_key());
  ParticleBatch warm;
  const glm::dvec3 ahead = v.camera.orientation * glm::dvec3(0.0, 0.0, -4.0 * v.camera.near_plane);
  // Hard, linear, the contrast curve, density extent, and both in one run.
  struct Warm {
    SoftEdge method;
    bool contrast, density_extent;
  };
  for (Warm w : {Warm{SoftEdge::Off, false, false}, Warm{SoftEdge::Linear, false, false},
                 Warm{SoftEdge::Contrast, true, false}, Warm{SoftEdge::DensityExtent, false, true},
                 Warm{SoftEdge::DensityExtent, true, true}}) {
    ParticleInstance p{};
    p.pos[0] = float(ahead.x), p.pos[1] = float(ahead.y), p.pos[2] = float(ahead.z);
    p.size = float(v.camera.near_plane) * 0.05f;  // a few pixels of white: a frame that failed to clear would show it
    p.color[0] = p.color[1] = p.color[2] = p.color[3] = 1.0f;
    p.soft_edge = uint8_t(w.method);
    warm.runs.push_back({uint32_t(warm.particles.size()), 1, w.method != SoftEdge::Off, w.contrast, w.density_extent, 1.0});
    warm.particles.push_back(p);
  }
  particles.upload(warm.particles);
  // The states the frame draws its particles in: the scene's origin (clip control's, top-down
  // scenes upper left), then the composite into the scene's colour alone with the origin as GL
  // stores it. Each is part of the variant's key: warmed in another (the composite into the
  // scene with depth, particles with the lower-left origin) the first half-resolution frame of
  // a fight still compiled its own, a hitch without the shader cache.
  set_origin(targets.top_down());
  targets.bind_scene();
  targets.copy_depth();
  ParticleFrame frame{vp, v.camera.fov_y_radians, float(v.camera.near_plane), targets.depth_copy(),
                      targets.scene_width(), targets.scene_height()};
  frame.depth_fetch = depth_fetch_usable();
  ParticleBatch indexed;  // the same particles drawn through an order (per cluster)
  const bool with_indexed = by_cluster();
  if (with_indexed) {
    indexed.source = &warm.particles;
    indexed.runs = warm.runs;
    for (size_t i = 0; i < warm.particles.size(); ++i) indexed.order.push_back(uint32_t(i));
  }
  particles.draw(warm, programs, rs, frame);
  if (with_indexed) {
    particles.upload(indexed);
    particles.draw(indexed, programs, rs, frame);
    particles.upload(warm.particles);
  }
  frame.depth_copy = targets.scene_depth();
  begin_half_resolution(frame);
  particles.draw(warm, programs, rs, frame);
  if (with_indexed) {
    particles.upload(indexed);
    particles.draw(indexed, programs, rs, frame);
  }
  set_origin(false);
  half_particles.composite(programs.particle_composite, targets.scene_color_fbo(), targets.scene_width(),
                           targets.scene_height(), {PixelRect{0, 0, 1, 1}});
  particles.forget_fragments();
}

// Bloom (HDR only) reads the finished scene; the post pass then tone-maps and/or filters it
// into the output, or blits it there when neither is on.
void Renderer::Impl::post_process(int width, int height) {
  PostInput in;
  in.scene = targets.scene_color();
  in.scene_w = targets.scene_width();
  in.scene_h = targets.scene_height();
  in.hdr = rs.hdr;
  in.exposure = rs.exposure;
  in.fxaa = rs.antialias == RenderSettings::Antialias::Fxaa;
  if (rs.hdr && rs.bloom > 0.0f) {
    in.bloom = bloom.run(in.scene, in.scene_w, in.scene_h, programs);
    in.bloom_strength = rs.bloom / float(bloom.summed_levels());
    stats.draw_calls += BloomPass::kLevels + BloomPass::kLevels - 2;
  }
  post.run(in, programs, targets, width, height);
  stats.draw_calls += (rs.hdr || in.fxaa) ? 1 + (rs.hdr && in.fxaa) : 0;
}

Image Renderer::read_pixels() { return impl_->targets.read_pixels(); }

std::vector<float> Renderer::read_pixels_float() { return impl_->targets.read_pixels_float(); }

// The fragment count is read back here, once the frame has been submitted: reading it inside
// the particle pass stalled the frame halfway (the passes after it waited for the particles).
FrameStats Renderer::last_stats() const {
  const long long fragments = impl_->particles.take_fragments();
  if (fragments >= 0) impl_->stats.particle_fragments = fragments;
  return impl_->stats;
}

std::string Renderer::reload() { return impl_->programs.reload(); }

double Renderer::draw_fill_reference(int count) {
  Impl& m = *impl_;
  if (!m.targets.has_scene()) throw std::logic_error("draw_fill_reference before any render");
  const int w = m.targets.scene_width(), h = m.targets.scene_height();
  HudLayer layer;
  for (int i = 0; i < count; ++i) layer.quads.push_back({0, 0, float(w), float(h), glm::vec4(0.02f, 0.01f, 0.005f, 0.05f)});
  m.targets.bind_scene();
  m.timers.begin_pass_timer();
  m.stats.draw_calls += m.hud.draw(layer, m.programs.hud, w, h);
  return m.timers.end_pass_timer();
}

void Renderer::finish() { glFinish(); }

void Renderer::count_particle_fragments(bool on) { impl_->particles.count_fragments(on); }

void Renderer::time_gpu_passes(bool on) { impl_->timers.time_passes(on); }

}  // namespace arc
