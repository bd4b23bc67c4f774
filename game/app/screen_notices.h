// game/app/screen_notices.h — the window's passing notice line and its FPS counter (no GL).
//
// A notice ("Sound muted (M)", "Recording stopped ...") shows for a given number of seconds
// of window time, the newest replacing any other. The frame rate is counted over at least
// half a second of frames, so the number on screen stays readable.
//
// Example, compiled as ScreenNotices.NoticeExpiresAndFpsCounts in tests/unit/app/test_screen_notices.cpp:
//   ScreenNotices notices;
//   notices.show("Sound muted (M)", now, 2.0);  // until now + 2 s
//   notices.count_frame(frame_seconds);          // every frame
//   hud.notice = notices.notice(now);            // "" once it has expired
//   hud.fps = notices.fps();
#pragma once
#include <string>

namespace arc {

class ScreenNotices {
 public:
  static constexpr double kFpsWindowSeconds = 0.5;

  void show(std::string text, double now, double seconds) {
    text_ = std::move(text);
    until_ = now + seconds;
  }
  std::string notice(double now) const { return now < until_ ? text_ : ""; }

  // One frame of `seconds`: the rate is measured again once half a second has gathered.
  void count_frame(double seconds) {
    ++frames_;
    seconds_ += seconds;
    if (seconds_ < kFpsWindowSeconds) return;
    fps_ = frames_ / seconds_;
    frames_ = 0;
    seconds_ = 0;
  }
  double fps() const { return fps_; }  // 0 until the first half second

 private:
  std::string text_;
  double until_ = 0;
  int frames_ = 0;
  double seconds_ = 0, fps_ = 0;
};

}  // namespace arc
