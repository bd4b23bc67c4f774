// The window's notice line and FPS counter (game/app/screen_notices.h), by window time alone.
#include <gtest/gtest.h>

#include "game/app/screen_notices.h"
#include "game/render/hud_layout.h"

namespace arc {
namespace {

TEST(ScreenNotices, NoticeExpiresAndFpsCounts) {
  HudState hud;
  double now = 10.0, frame_seconds = 0.1;

  ScreenNotices notices;
  notices.show("Sound muted (M)", now, 2.0);  // until now + 2 s
  notices.count_frame(frame_seconds);          // every frame
  hud.notice = notices.notice(now);            // "" once it has expired
  hud.fps = notices.fps();

  EXPECT_EQ(hud.notice, "Sound muted (M)");
  EXPECT_EQ(hud.fps, 0.0) << "no rate before half a second of frames";
  EXPECT_EQ(notices.notice(11.9), "Sound muted (M)");
  EXPECT_EQ(notices.notice(12.0), "");
  notices.show("Recording stopped", 12.0, 8.0);
  notices.show("Sound on (M)", 12.5, 2.0);  // the newest replaces it
  EXPECT_EQ(notices.notice(13.0), "Sound on (M)");
  EXPECT_EQ(notices.notice(15.0), "");
  for (int i = 0; i < 3; ++i) notices.count_frame(frame_seconds);
  EXPECT_EQ(notices.fps(), 0.0);
  notices.count_frame(frame_seconds);  // five frames in half a second
  EXPECT_NEAR(notices.fps(), 10.0, 1e-9);
  for (int i = 0; i < 31; ++i) notices.count_frame(1.0 / 60);
  EXPECT_NEAR(notices.fps(), 60.0, 1e-9) << "measured again over the next half second";
}

}  // namespace
}  // namespace arc
