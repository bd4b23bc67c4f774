// game/workbench/game_panel.h — the F1 panel of the running game (ImGui over the game window).
//
// For developers: F1 opens it only with --dev or the player's "developer panel" setting, and it
// pauses the fight while open (game/app/dev_panel_gate.h).
//
// Two tabs: every setting `--list-settings` prints, each with the widget its kind wants over its
// allowed range, and the effect list, where an effect opens in the workbench's field editor
// (game/workbench/panel_fields.h) and Save writes it, so the game's hot reload restarts the
// level with it. Render and audio keys act at once; the simulation's keys (particles.*, sim.*)
// at the next start of a level, because a game's simulation is fixed when it starts (replays
// depend on it). A line of figures (FPS, particles drawn, the particle pass's time) shows what
// a change costs.
//
// One GamePanel(root_dir) is made once the window is open. Each frame, before the swap, frame()
// draws it over the game with the settings and the renderer's last figures, and returns true
// when a setting changed, for the caller to apply (the renderer's apply_settings(), the mix).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/settings.h"
#include "game/workbench/effect_document.h"
#include "game/workbench/panel_fields.h"
#include "gfx/renderer.h"
#include "gfx/ui_texture.h"
#include "ui/imgui_layer.h"

namespace arc {

class GamePanel {
 public:
  explicit GamePanel(std::string root_dir);
  void toggle() { open_ = !open_; }
  bool open() const { return open_; }
  // Draws the panel when open (and nothing otherwise); true when a setting changed this frame.
  bool frame(Settings& settings, const FrameStats& stats);
  bool wants_mouse() const { return open_ && ui_.wants_mouse(); }

 private:
  bool draw_settings(Settings& settings);
  void draw_effects();

  std::string root_dir_;
  ImGuiLayer ui_;
  bool open_ = false;
  std::string settings_error_;
  std::vector<std::string> effect_files_;
  std::unique_ptr<EffectDocument> doc_;
  std::string effect_message_;
  EffectPanel fields_;
  std::vector<std::unique_ptr<UiTexture>> thumbnails_;  // the sprite picker's
};

}  // namespace arc
