// gfx/gpu_timers.cpp — the particle pass's timer query ring and the synchronous pass timer.
#include "gfx/gpu_timers.h"

namespace arc {

GpuTimers::GpuTimers() { glGenQueries(GLsizei(ring_.size()), ring_.data()); }

GpuTimers::~GpuTimers() {
  glDeleteQueries(GLsizei(ring_.size()), ring_.data());
  if (pass_query_) glDeleteQueries(1, &pass_query_);
}

void GpuTimers::collect_finished() {
  // Collect the oldest finished timer query so reading it never stalls.
  for (size_t i = 0; i < ring_.size(); ++i) {
    if (!pending_[i]) continue;
    GLint ready = 0;
    glGetQueryObjectiv(ring_[i], GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(ring_[i], GL_QUERY_RESULT, &ns);
      last_gpu_ms_ = double(ns) * 1e-6;
      pending_[i] = false;
    }
  }
  index_ = (index_ + 1) % int(ring_.size());
}

void GpuTimers::begin_particle_pass() {
  ring_running_ = !time_passes_ && !pending_[size_t(index_)];
  if (ring_running_) glBeginQuery(GL_TIME_ELAPSED, ring_[size_t(index_)]);
  begin_pass_timer();
}

double GpuTimers::end_particle_pass() {
  const double ms = end_pass_timer();
  if (ring_running_) {
    glEndQuery(GL_TIME_ELAPSED);
    pending_[size_t(index_)] = true;
    ring_running_ = false;
  }
  return ms;
}

void GpuTimers::begin_pass_timer() {
  if (!time_passes_) return;
  if (!pass_query_) glGenQueries(1, &pass_query_);
  glBeginQuery(GL_TIME_ELAPSED, pass_query_);
}

double GpuTimers::end_pass_timer() {
  if (!time_passes_) return -1.0;
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 ns = 0;
  glGetQueryObjectui64v(pass_query_, GL_QUERY_RESULT, &ns);
  return double(ns) * 1e-6;
}

}  // namespace arc
