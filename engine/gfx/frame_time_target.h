// gfx/frame_time_target.h — the frame-time target the particle budgets follow (no GL).
//
// render.target_frame_ms names the frame time a player should get. The caller hands each
// frame's measured time to observe() (the window loop its frame interval, the bench its timed
// frame); level() is then a quality level in [kMinLevel, 1] that the renderer multiplies into
// the overdraw budget's screen layers and into the layers at which render.particle_resolution
// = auto goes to half resolution, and from which it takes the size under which small particles
// of low and normal screen priority are left out (min_px: a software rasteriser pays for each
// particle drawn, and in a big merge their number, not their fill, is most of the frame; see
// renderer.cpp and overdraw_budget.h). Level 1 is the settings as they are: nothing
// changes until frames run over the target, and a run that never reports a frame time (the
// headless replays and their image snapshots) keeps level 1 and its pictures.
//
// A controller with damping and hysteresis, so the budget does not pump:
//  - the frame time is smoothed in log space, quickly toward slower frames (a quarter of the
//    way a frame), slowly toward faster ones (a tenth), and a single frame is clamped to
//    [target / 4, target · 4] first, so one hitch (a window drag, a compile) moves it little;
//  - over kOverShare of the target the level falls in proportion to the excess (at most
//    kMaxFall of it a frame); under kUnderShare it rises in proportion to the headroom (at most
//    kMaxRise a frame), and not within kHoldFrames of the last fall; in between it holds: a
//    deadband wide enough that the level settles instead of cycling around the target;
//  - a frame at or under the target whose picture the level did not change (no particle
//    reduced, full resolution) lets the level rise as well: under vsync a frame never reads
//    faster than the display's interval, and raising an unused level changes nothing seen.
// The overdraw budget's own per-cluster smoothing (overdraw_budget.h) spreads each change of
// the layers over several frames as well.
//
// Example, compiled as GfxCpuExamples.FrameTimeTarget in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   FrameTimeTarget t;
//   t.set_target(16.7);
//   t.observe(40.0, true);  // a slow frame: level() falls below 1
#pragma once

namespace arc {

class FrameTimeTarget {
 public:
  static constexpr double kMinLevel = 0.1;    // the lowest level: a tenth of the layers
  static constexpr double kOverShare = 1.05;  // smoothed time over target × this: the level falls
  static constexpr double kUnderShare = 0.85; // under target × this: it may rise
  static constexpr double kMaxFall = 0.08;    // at most 8 % of the level a frame
  static constexpr double kMaxRise = 0.02;    // at most 2 % a frame
  static constexpr int kHoldFrames = 30;      // frames after a fall before it may rise

  // 0 (or less): no target, level 1. Keeps the state when the target stays the same.
  void set_target(double ms);
  double target() const { return target_ms_; }
  // One frame's time, ms, and whether the level changed that frame's picture (particles
  // reduced or drawn at half resolution).
  void observe(double frame_ms, bool level_in_use);
  double level() const { return level_; }
  // The on-screen extent, pixels, under which the budget leaves out particles below high
  // screen priority (OverdrawOptions::min_px): 0 at level 1, kMinPxAtFloor (at 720 rows, in
  // proportion to `rows`) at kMinLevel.
  double min_px(int rows) const;
  static constexpr double kMinPxAtFloor = 3.0;
  double smoothed_ms() const;  // 0 before the first frame
  void reset();

 private:
  double target_ms_ = 0;
  double level_ = 1.0;
  double log_smoothed_ = 0;
  bool has_frame_ = false;
  int since_fall_ = kHoldFrames;
};

}  // namespace arc
