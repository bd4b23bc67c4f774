// game/render/camera_settings.h — how the frame's camera is set up, apart from the HUD.
//
// The World owns the camera rig (smoothed in the simulation, so replays agree) and its mode
// (chase, cockpit, or the level's fixed camera); CameraSettings lets the app or a tool
// override the mode and the field of view without touching the simulation. What the HUD shows
// (FPS counter, pause menu) is HudState in game/render/hud_layout.h.
#pragma once
#include <cstdint>
#include <optional>

namespace arc {

enum class CameraMode : uint8_t;  // game/sim/world.h

struct CameraSettings {
  std::optional<CameraMode> mode;  // absent: the World's camera mode
  double fov_deg = 0;              // 0: the level's camera hint
};

}  // namespace arc
