#include <gtest/gtest.h>

#include "core/clock.h"

using arc::FixedStepClock;

TEST(FixedStepClock, RunsWholeTicksAndKeepsRemainderAsAlpha) {
  FixedStepClock c{60};
  EXPECT_EQ(c.advance(1.0 / 60.0 * 2.5), 2);
  EXPECT_NEAR(c.alpha(), 0.5, 1e-9);
  EXPECT_EQ(c.advance(1.0 / 60.0 * 0.5), 1);
  EXPECT_NEAR(c.alpha(), 0.0, 1e-9);
}

TEST(FixedStepClock, SumOfTicksMatchesElapsedTimeOverManyFrames) {
  FixedStepClock c{60};
  long total = 0;
  for (int i = 0; i < 6000; ++i) total += c.advance(1.0 / 144.0);  // 6000 frames at 144 Hz
  double expected = 6000.0 / 144.0 * 60.0;
  EXPECT_NEAR(double(total) + c.alpha(), expected, 1e-6);
}

TEST(FixedStepClock, LongFrameIsClampedSoItCannotSpiral) {
  FixedStepClock c{60, 0.25};
  EXPECT_EQ(c.advance(10.0), 15);  // 0.25 s at 60 Hz
  EXPECT_EQ(c.clamped_frames(), 1u);
}

// The window loop's frame clock at the extremes: a 0.25 s hitch is exactly the most one frame
// may owe, a 5 s stall (a breakpoint, a dragged window) owes no more than that, and the frame
// after either owes only its own time: no backlog carries over, so nothing spirals.
TEST(FixedStepClock, HitchOfAQuarterSecondAndStallOfFiveSecondsAtEveryTickRate) {
  for (int rate : {20, 60, 480}) {  // rates where a quarter second is whole ticks
    FixedStepClock c{rate, 0.25};
    EXPECT_EQ(c.advance(0.25), rate / 4) << rate << " Hz";
    EXPECT_EQ(c.clamped_frames(), 0u) << rate << " Hz";
    EXPECT_EQ(c.advance(5.0), rate / 4) << rate << " Hz";
    EXPECT_EQ(c.clamped_frames(), 1u) << rate << " Hz";
    EXPECT_EQ(c.advance(1.0 / rate), 1) << rate << " Hz: the stall left a backlog";
    EXPECT_LT(c.alpha(), 1.0);
  }
}

TEST(FixedStepClock, PauseRunsNoTicksAndResumesCleanly) {
  FixedStepClock c{60};
  c.advance(0.01);
  c.set_paused(true);
  EXPECT_EQ(c.advance(1.0), 0);
  c.set_paused(false);
  EXPECT_EQ(c.alpha(), 0.0);
  EXPECT_EQ(c.advance(1.0 / 60.0), 1);
}

TEST(FixedStepClock, BadFrameTimesAreIgnored) {
  FixedStepClock c{60};
  EXPECT_EQ(c.advance(-1.0), 0);
  EXPECT_EQ(c.advance(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(c.advance(std::numeric_limits<double>::infinity()), 15);
  EXPECT_GE(c.alpha(), 0.0);
  EXPECT_LT(c.alpha(), 1.0);
}
