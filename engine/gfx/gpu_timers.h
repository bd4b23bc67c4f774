// gfx/gpu_timers.h — GL_TIME_ELAPSED queries around the particle pass (timer queries are core
// since GL 3.3, the renderer's baseline).
//
// Two ways, for two readers. By default a ring of three queries times the particle pass of
// every frame and reads each back frames later, once its result is available, so it never
// stalls: FrameStats::particle_gpu_ms is that of an earlier frame. With time_passes on (the
// benchmark), one query around the pass, or around the fill reference, is read back at once:
// it stalls, but gives this frame's figure; the ring rests meanwhile (two GL_TIME_ELAPSED
// queries cannot nest).
//
// Example, compiled as GlExamples.GpuTimers in tests/unit/gfx/test_gl_examples.cpp:
//   GpuTimers timers;
//   timers.collect_finished();                 // at the start of a frame
//   timers.begin_particle_pass();
//   targets.copy_depth();                      // and the particle draws
//   double ms = timers.end_particle_pass();    // −1 unless time_passes is on
#pragma once
#include <epoxy/gl.h>

#include <array>

namespace arc {

class GpuTimers {
 public:
  GpuTimers();
  ~GpuTimers();
  GpuTimers(const GpuTimers&) = delete;
  GpuTimers& operator=(const GpuTimers&) = delete;

  // Reads every ring query whose result is ready and moves to the next slot of the ring.
  void collect_finished();
  // The latest result the ring read: ms of an earlier frame's particle pass, −1 before any.
  double last_particle_gpu_ms() const { return last_gpu_ms_; }

  void begin_particle_pass();
  double end_particle_pass();  // this pass's ms when time_passes is on, else −1

  void time_passes(bool on) { time_passes_ = on; }
  // A synchronous timer around any pass (the fill reference): no-ops returning −1 unless
  // time_passes is on.
  void begin_pass_timer();
  double end_pass_timer();

 private:
  std::array<GLuint, 3> ring_{};
  std::array<bool, 3> pending_{};
  int index_ = 0;
  bool ring_running_ = false;  // the ring's query is open around this frame's particle pass
  double last_gpu_ms_ = -1;
  bool time_passes_ = false;
  GLuint pass_query_ = 0;
};

}  // namespace arc
