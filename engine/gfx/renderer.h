// gfx/renderer.h — the OpenGL 3.3 renderer: sky, lit glTF meshes, particles, HUD.
//
// Needs a current GL context (platform/ makes one: a GLFW window or EGL headless). Each frame
// draws into an internal scene framebuffer at the window size × render.scale, then resolves it
// to the window (default framebuffer) or, with RendererDesc::offscreen, to an RGBA8 target that
// read_pixels() returns. With render.hdr the scene is linear light in a float buffer, and the
// resolve is a tone map (with bloom and FXAA as set); without it, 8-bit display values are
// blitted. The frame is a fixed sequence of passes, one file pair each (sky_pass, mesh_pass,
// particle_batch + particle_pass, bloom_pass, post_pass, hud_pass over render_targets,
// shader_programs and gpu_timers); which pass reads what the previous one wrote is stated once,
// at the top of renderer.cpp. Depth is reversed-Z with a float buffer when clip control exists, standard
// otherwise. All positions reach the GPU relative to the camera (double subtraction, then float).
//
// Example, compiled as RendererExample.DrawsAView in tests/unit/gfx/test_examples.cpp:
//   Renderer renderer({.offscreen = true});
//   ModelId ship = renderer.add_model(load_model(data_root() + "/assets/models/viper.glb"));
//   RenderView view;
//   view.meshes.push_back({ship, {0, 0, -20}});
//   renderer.set_sprites({load_sprite(data_root() + "/assets/textures/sprite_smoke.png")});
//   Settings settings;
//   register_render_settings(settings);  // the render.* keys at their defaults
//   renderer.apply_settings(settings);
//   renderer.render(view, 640, 360);
//   Image frame = renderer.read_pixels();
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "assets/model.h"
#include "core/data_root.h"
#include "core/settings.h"
#include "gfx/render_settings.h"
#include "gfx/render_view.h"

namespace arc {

struct RendererDesc {
  std::string shader_dir = data_root() + "/shaders";  // core/data_root.h
  bool offscreen = false;  // resolve into an RGBA8 target for read_pixels() instead of the window
  bool float_scene = false;  // RGBA16F scene buffer: NaN/Inf survive to read_pixels_float()
  // The float format of the HDR scene buffer (render.hdr); post_pass.h says why RGBA16F.
  HdrFormat hdr_format = HdrFormat::Rgba16f;
  // Particles one draw can pull from its buffer texture: GL_MAX_TEXTURE_BUFFER_SIZE / 4, or
  // this when it is smaller and not 0 (tests use it to reach the limit).
  size_t max_particles_per_draw = 0;
  // The scene stored top row first (SceneFormat::top_down in render_targets.h) in frames whose
  // post pass is a plain resolve (8-bit scene, no FXAA or MSAA) when clip control exists. A
  // window system keeps a window's rows top first, so the resolve into it becomes a copy of rows
  // instead of a flipping, converting draw (several times cheaper on llvmpipe under Xvfb;
  // docs/performance.md). Auto: for a window only (an offscreen target's rows are bottom first,
  // and the resolve into it is a copy already); On: offscreen too, which tests use to check that
  // the picture is the same either way.
  enum class TopDownScene { Auto, Off, On } top_down_scene = TopDownScene::Auto;
};

struct FrameStats {
  int particles_in = 0;      // instances handed in by the view
  int particles_drawn = 0;   // after dropping invisible ones (zero alpha and zero colour) and culling
  int culled_offscreen = 0;  // particles whose quad lies wholly outside the view frustum's sides
  int over_draw_limit = 0;   // farthest particles left out: more than one buffer texture holds
  int sorted = 0;            // particles put in back-to-front order
  bool depth_copied = false; // the soft-edge depth copy ran this frame (full resolution only: at half
                             // resolution soft edges read the scene depth itself)
  bool depth_fetched = false; // soft edges read the depth from the framebuffer instead (RenderSettings::depth_fetch)
  bool reads_depth() const { return depth_copied || depth_fetched; }  // soft edges read the opaque depth
  int soft_shaded = 0;       // particles that read the depth copy: soft edges on and an opaque
                             // mesh within their reach (the others' soft factor is exactly 1)
  int draw_calls = 0;
  int particle_draw_calls = 0;  // one per run of the particle batch (particle_runs.h)
  // The overdraw budget (overdraw_budget.h): estimated blended layers (pixels ÷ scene pixels)
  // before and after it, particles it shrank or faded, those it faded out, and its cap k.
  double overdraw_estimated_layers = 0;
  double overdraw_budgeted_layers = 0;
  int particles_reduced = 0;
  int particles_dropped = 0;
  double overdraw_cap = 0;
  bool particles_half_res = false;    // drawn at half resolution (render.particle_resolution)
  double frame_level = 1.0;           // the frame-time target's level this frame (frame_time_target.h)
  double composite_share = 0;         // share of the screen the half-resolution composite covered
  double particle_target_pixels = 0;  // pixels of the target the particles blended into (a quarter with half resolution)
  int msaa_samples = 0;        // samples of the opaque pass (0: no MSAA; drivers may give more than asked)
  double particle_prep_ms = 0; // culling, soft-edge flags and sorting, before any GL call
  double particle_cpu_ms = 0;  // all of the pass on the CPU: preparation, upload, draw submission
                               // (on llvmpipe submission includes vertex work, binning and any
                               // wait for earlier passes the depth copy needs)
  // Where the frame's wall-clock time goes on the CPU, pass by pass (render() to its return):
  // submitting the opaque pass (clear, sky, meshes, MSAA resolve), the particle pass's target
  // (the depth copy, or the half-resolution target taking the scene's depth), its half-
  // resolution composite, the post pass and the HUD. On a GPU these are submission costs; on
  // llvmpipe, which rasterises a pass before a later one may read it, the target step also
  // waits for the opaque pass to be rasterised and the composite for the particles, so the
  // split says where a slow frame's time goes (`--scene combat_view` prints it for the slowest
  // frames).
  double opaque_cpu_ms = 0;
  double particle_target_cpu_ms = 0;
  double particle_composite_cpu_ms = 0;
  double post_cpu_ms = 0;
  double hud_cpu_ms = 0;
  double particle_gpu_ms = -1; // GL_TIME_ELAPSED of the particle pass of an earlier frame; −1 if unknown
  long long particle_fragments = -1;  // samples the particle draw blended (count_particle_fragments); −1 if not counted
  double particle_pass_gpu_ms = -1;   // GL_TIME_ELAPSED of this frame's particle pass (time_gpu_passes); −1 if not timed
};

// One line of a frame's particle figures for an on-screen counter: particles drawn (and how
// many the overdraw budget reduced), particle draws, estimated blended layers.
std::string describe_particle_stats(const FrameStats& s);

class Renderer {
 public:
  // Throws PlatformError-like std::runtime_error when GL is older than 3.3 or shaders fail.
  explicit Renderer(const RendererDesc& desc);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  std::string gl_version() const;
  // GL_RENDERER: the device that draws ("llvmpipe (LLVM 15.0.6, 256 bits)", a GPU's name).
  std::string gl_renderer() const;
  bool has_clip_control() const;

  ModelId add_model(const ModelData& model);  // the id MeshInstance::model refers to
  void set_sprites(const std::vector<Image>& premultiplied_sprites);  // layers of one array texture
  void apply_settings(const Settings& settings);  // render.* keys
  void set_render_settings(const RenderSettings& s);
  const RenderSettings& render_settings() const;

  void render(const RenderView& view, int width, int height);
  // Forgets what smooths from frame to frame (the overdraw budget's cap): the next frame is
  // drawn as if it were the first, e.g. after a cut to an unrelated view.
  void restart_smoothing();
  // The frame that was last drawn took `ms` (the window loop: its frame interval): the level the
  // budgets follow under render.target_frame_ms moves (frame_time_target.h). A renderer never
  // told keeps its settings as they are.
  void report_frame_time(double ms);
  double frame_level() const;
  // Work a coming view would do in its first frame, done ahead a slice at a time (one face of
  // the nebula for `starfield_seed`); true when nothing is left. For a mission about to launch.
  bool warm_sky(uint64_t starfield_seed);
  Image read_pixels();                      // offscreen only; RGBA8, rows top to bottom
  std::vector<float> read_pixels_float();   // offscreen only; the scene buffer as RGBA floats, rows top to bottom
  FrameStats last_stats() const;

  // Recompiles all shaders from the shader folder. On error the old programs stay and the
  // error text is returned; an empty string means success.
  std::string reload();

  // For the benchmark's raw fill-rate reference: draws `count` full-screen quads with the
  // particle blend state into the scene buffer of the last frame's size. Returns their
  // GL_TIME_ELAPSED in ms when time_gpu_passes is on and the context has timer queries, else −1.
  double draw_fill_reference(int count);
  // Blocks until the GPU has finished all submitted work (glFinish), for timing.
  void finish();
  // For the benchmark: count the fragments the particle draw blends (an occlusion query read
  // back by last_stats(), which then waits for the particle pass; off by default).
  void count_particle_fragments(bool on);
  // For the benchmark: time this frame's particle pass (depth copy and draw) and the fill
  // reference with GL_TIME_ELAPSED queries read back at once (stalls; off by default). On a
  // GPU that is the pass's GPU time without the CPU's sorting and upload; on llvmpipe it
  // covers only the rasteriser threads, not vertex processing and binning.
  void time_gpu_passes(bool on);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace arc
