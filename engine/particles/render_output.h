// particles/render_output.h — what the particle engine hands to the renderer each frame.
//
// One ParticleInstance per visible particle, with a float position relative to the camera
// (computed from double-precision world positions), so precision does not depend on where in
// space the scene is. The renderer builds the quads on the GPU from an array of these.
#pragma once
#include <cstdint>

namespace arc {

enum class SoftEdge : uint8_t {
  Off = 0,
  Linear = 1,          // Ilmonen 2006 §3: alpha · clamp((zb − z) / size)
  Contrast = 2,        // Lorach 2007 contrast curve on the same difference
  AverageDensity = 3,  // Krazanowski: (zb − z) / extent over the volume
  DensityExtent = 4,   // Krazanowski: texture alpha as the volume's extent
};

// Which particles the renderer's overdraw budget (render.overdraw_budget) shrinks, fades and
// drops first when a frame would blend more screen layers than it allows: sparks and debris
// before shields, smoke and trails, before beams and fireballs.
enum class ScreenPriority : uint8_t { Low = 0, Normal = 1, High = 2 };

enum class Billboard : uint8_t {
  CameraFacing = 0,  // rotated by `rotation` around the view axis
  AxisLocked = 1,    // long axis along `axis`, turned to face the camera around it
};

// 64 bytes, laid out for a single instanced vertex buffer.
struct ParticleInstance {
  float pos[3];     // centre, camera-relative world units
  float size;       // half-width, world units
  float axis[3];    // AxisLocked: full segment vector (world units): a lightning segment, or a
                    // streak's velocity × stretch; CameraFacing: unused
  float rotation;   // radians around the view axis (CameraFacing)
  float color[4];   // rgb premultiplied by alpha (Ilmonen eq. 5: fgc = rgb·alpha), then alpha
  float burn;       // 0 = alpha blended, 1 = additive
  float soft_extent;  // depth extent of the volume for soft edges (world units); ≤ 0 → use size
  uint8_t sprite;     // layer in the sprite array texture (at most 256 sprites)
  uint8_t screen_priority;  // ScreenPriority: which particles an overdraw budget reduces first
  uint8_t soft_edge;  // SoftEdge
  uint8_t billboard;  // Billboard
  uint32_t cluster;   // cluster index, for per-cluster sorting
};
static_assert(sizeof(ParticleInstance) == 64, "ParticleInstance is uploaded as-is");

}  // namespace arc
