// `--frame-times` (game/app/frame_time_log.h): one CSV line per window frame with the renderer's
// own split of it, and the median frame's split against the rest of the frame (simulation,
// menus, swap), the first second left out.
#include <gtest/gtest.h>

#include <string>

#include "game/app/frame_time_log.h"
#include "gfx/renderer.h"

namespace arc {
namespace {

FrameStats split(double opaque, double particles, double post, double hud) {
  FrameStats s;
  s.opaque_cpu_ms = opaque;
  s.particle_cpu_ms = particles;
  s.post_cpu_ms = post;
  s.hud_cpu_ms = hud;
  return s;
}

int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(FrameTimeLog, TheMedianFrameIsSplitIntoTheRendererAndTheRest) {
  FrameTimeLog log("unused.csv");
  // Warm-up: a slow first frame that the median must not see.
  log.frame(0.200, 0.0, 1, split(100, 50, 20, 10));
  // Past the first second: 10, 20 (the median) and 30 ms frames.
  log.frame(0.010, 1.5, 2, split(2, 3, 1, 0.5));
  log.frame(0.030, 1.6, 3, split(3, 20, 2, 1));
  log.frame(0.020, 1.7, 4, split(4, 9, 2, 1));
  EXPECT_EQ(log.median_split(),
            "arcfire: median frame 20.0 ms: render 16.0 ms (opaque 4.0, particles 9.0, post 2.0, hud 1.0), the rest 4.0 ms");
  const std::string csv = log.csv();
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "time_s,frame_ms,tick,particles_drawn,budgeted_layers,half_res,render_opaque_ms,render_particles_ms,"
            "render_post_ms,render_hud_ms");
  EXPECT_EQ(lines(csv), 5);
  EXPECT_NE(csv.find("1.7000,20.000,4,0,0.000,0,4.000,9.000,2.000,1.000\n"), std::string::npos);
}

TEST(FrameTimeLog, NoMedianUnderTheWarmUp) {
  FrameTimeLog log("unused.csv");
  log.frame(0.016, 0.0, 1, split(1, 1, 1, 1));
  log.frame(0.016, 0.5, 2, split(1, 1, 1, 1));
  EXPECT_EQ(log.median_split(), "");
  EXPECT_EQ(lines(log.csv()), 3);
  EXPECT_FALSE(FrameTimeLog("").enabled());
}

}  // namespace
}  // namespace arc
