#include "gfx/render_settings.h"

#include "core/settings.h"

namespace arc {

// Each doc ends with the setting's cost class; docs/performance.md has the figures.
void register_render_settings(Settings& s) {
  s.define_choice("render.soft_edges", "effect",
                  {"effect", "off", "linear", "contrast", "average_density", "density_extent"},
                  "soft-edge method: 'effect' uses each effect's own, others override all effects; cheap");
  s.define_choice("render.sorting", "full", {"off", "cluster", "full"},
                  "back-to-front order of non-additive particles: none, by cluster, or per particle;"
                  " cheap (CPU time, full the most)");
  s.define_choice("render.particle_prep", "auto", {"auto", "particle", "cluster"},
                  "particle preparation on the CPU: per particle (budget, runs; for a software rasteriser) or per"
                  " cluster (a tenth of the CPU time, no budget; for a GPU); auto picks by device");
  s.define_choice("render.particle_sort_bits", "22", {"11", "22", "32"},
                  "depth key bits of the per-cluster full sort: 11 or 22 quantise the depth over the drawn range"
                  " (one radix pass per 11 bits), 32 is the exact depth; fewer bits cost less CPU time");
  s.define_choice("render.depth_mode", "reversed", {"reversed", "standard"},
                  "reversed-Z float depth (needs clip control) or standard depth; no cost");
  s.define_flag("render.infinite_far", true, "infinite far plane; no cost");
  s.define_choice("render.texture_filter", "mipmap_nearest", {"nearest", "linear", "mipmap_nearest", "mipmap"},
                  "sprite and model texture filtering: mipmap_nearest is bilinear within one mip level, mipmap"
                  " trilinear (between two levels: twice the texel reads, costly on a software rasteriser)");
  s.define_number("render.scale", 1.0, 0.25, 2.0,
                  "render resolution relative to the window; costs fill rate with its square");
  s.define_number("render.particle_size_clamp", 0.5, 0.01, 4.0,
                  "largest particle size on screen, as a fraction of screen height; larger costs fill rate up close");
  s.define_number("render.near_fade", 2.0, 0.0, 100.0,
                  "distance in world units over which particles fade out toward the camera; no cost");
  s.define_number("render.contrast_power", 2.0, 0.5, 8.0, "exponent of the contrast soft-edge curve; no cost");
  s.define_choice("render.sky", "baked", {"baked", "exact"},
                  "nebula background: baked once per level into a cube map, or evaluated per pixel every frame;"
                  " exact is costly on a software rasteriser");
  s.define_integer("render.sky_resolution", 256, 16, 1024,
                   "texels along each face of the baked nebula cube map; costs memory and level-load time");
  s.define_integer("render.sky_grid", 32, 0, 64,
                   "baked nebula looked up every N pixels and interpolated between (0: at every pixel);"
                   " a finer grid costs fill rate");
  s.define_number("render.overdraw_budget", 3.0, 0.0, 64.0,
                  "screen layers of particle blending per frame before the nearest, largest particles are shrunk,"
                  " faded and dropped (low screen priority first); 0: no budget; caps the particles' fill rate");
  s.define_choice("render.particle_resolution", "auto", {"full", "half", "auto"},
                  "particles blended at the scene's resolution, or at half its width and height and put over it"
                  " (a quarter of the blending, softer particles), or auto: half while they blend more than one"
                  " screen layer, full again under 0.6; half saves fill rate");
  s.define_number("render.target_frame_ms", 16.7, 0.0, 1000.0,
                  "frame time, ms, that the overdraw budget and the particle resolution follow from frame to frame:"
                  " slower frames shrink the budget, leave out the smallest particles and go to half resolution"
                  " sooner, faster ones give it back; 0: off; saves fill rate when frames run late");
  s.define_number("render.overdraw_near", 40.0, 1.0, 1e6,
                  "distance in world units within which the overdraw budget reduces particles at full strength;"
                  " no cost");
  // HDR, bloom and the edge filter are the look of the high and reference presets and of the
  // attract demo; the default keeps the 8-bit scene because a software rasteriser cannot afford
  // them at 60 Hz (docs/performance.md).
  s.define_flag("render.hdr", false,
                "linear-light float scene with a filmic tone curve (on), or 8-bit display colours (off);"
                " costs fill rate, costly on a software rasteriser");
  s.define_number("render.exposure", 1.0, 0.05, 16.0,
                  "scene brightness scale before the tone curve (render.hdr on); no cost");
  s.define_choice("render.bloom", "off", {"off", "low", "high"},
                  "glow around light brighter than white (render.hdr on): none, soft or strong;"
                  " costs fill rate, costly on a software rasteriser");
  s.define_choice("render.antialias", "off", {"off", "fxaa", "msaa2", "msaa4"},
                  "edge anti-aliasing: FXAA filter on the final image, or 2x/4x multisampling of the opaque pass;"
                  " costs fill rate and memory, costly on a software rasteriser");
}

}  // namespace arc
