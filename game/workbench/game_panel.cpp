// The game's F1 panel: settings and effects (see the header).
#include "game/workbench/game_panel.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <imgui.h>

#include "assets/image.h"
#include "core/data_layers.h"
#include "core/error.h"
#include "particles/sprites.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

bool simulation_key(const std::string& key) { return key.rfind("particles.", 0) == 0 || key.rfind("sim.", 0) == 0; }

// One setting's widget; the new value as text when it changed.
bool setting_widget(const SettingDef& d, std::string& text) {
  switch (d.kind) {
    case SettingDef::Kind::Number: {
      double v = std::stod(d.value);
      const bool slider = d.max - d.min <= 100.0;
      const bool changed = slider ? ImGui::SliderScalar(d.key.c_str(), ImGuiDataType_Double, &v, &d.min, &d.max, "%.3f")
                                  : ImGui::DragScalar(d.key.c_str(), ImGuiDataType_Double, &v,
                                                      float(std::max(0.01, std::abs(v) * 0.01)), &d.min, &d.max, "%.3f");
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.6g", v);
      text = buf;
      return changed;
    }
    case SettingDef::Kind::Integer: {
      int v = std::stoi(d.value);
      const int lo = int(d.min), hi = int(std::min(d.max, 2e9));
      const bool changed = hi - lo <= 100 ? ImGui::SliderInt(d.key.c_str(), &v, lo, hi)
                                          : ImGui::DragInt(d.key.c_str(), &v, float(std::max(1, std::abs(v) / 100)), lo, hi);
      text = std::to_string(v);
      return changed;
    }
    case SettingDef::Kind::Choice: {
      bool changed = false;
      if (ImGui::BeginCombo(d.key.c_str(), d.value.c_str())) {
        for (const std::string& c : d.choices)
          if (ImGui::Selectable(c.c_str(), c == d.value)) text = c, changed = c != d.value;
        ImGui::EndCombo();
      }
      return changed;
    }
    case SettingDef::Kind::Flag: {
      bool on = d.value == "true" || d.value == "on" || d.value == "1";
      const bool changed = ImGui::Checkbox(d.key.c_str(), &on);
      text = on ? "true" : "false";
      return changed;
    }
  }
  return false;
}

}  // namespace

GamePanel::GamePanel(std::string root_dir) : root_dir_(std::move(root_dir)) {
  effect_files_ = data_files(root_dir_, "assets/effects", ".json");
  std::vector<uint32_t> names;
  for (std::string_view name : kSpriteNames) {
    const std::string png = data_file(root_dir_, "assets/textures/sprite_" + std::string(name) + ".png");
    thumbnails_.push_back(std::make_unique<UiTexture>(load_image(png)));
    names.push_back(thumbnails_.back()->gl_name());
  }
  fields_.set_sprite_thumbnails(std::move(names));
}

bool GamePanel::frame(Settings& settings, const FrameStats& stats) {
  if (!open_) return false;
  ui_.begin_frame();
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(440, 560), ImGuiCond_FirstUseEver);
  bool changed = false;
  if (ImGui::Begin("Tweaks (F1)", &open_)) {
    ImGui::Text("%.0f FPS   %d particles drawn   particle pass %.2f ms", double(ImGui::GetIO().Framerate),
                stats.particles_drawn, stats.particle_cpu_ms);
    if (ImGui::BeginTabBar("tabs")) {
      if (ImGui::BeginTabItem("Settings")) {
        changed = draw_settings(settings);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Effects")) {
        draw_effects();
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
  ui_.end_frame();
  return changed;
}

bool GamePanel::draw_settings(Settings& settings) {
  bool changed = false;
  ImGui::TextDisabled("render.* and audio.* act now; particles.* and sim.* at the next level start");
  if (!settings_error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", settings_error_.c_str());
  ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  for (const SettingDef& d : settings.all()) {
    std::string text;
    if (simulation_key(d.key)) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.8f, 1.0f, 1.0f));
    const bool edited = setting_widget(d, text);
    if (simulation_key(d.key)) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.doc.c_str());
    if (!edited) continue;
    try {
      const std::string key = d.key;  // set() may move the definitions
      settings.set(key, text, "F1 panel");
      settings_error_.clear();
      changed = true;
    } catch (const InputError& e) {
      settings_error_ = e.what();
    }
  }
  ImGui::PopItemWidth();
  return changed;
}

void GamePanel::draw_effects() {
  for (const std::string& f : effect_files_) {
    std::error_code ec;
    const bool current = doc_ && fs::equivalent(doc_->path(), f, ec);
    if (ImGui::Selectable(fs::path(f).stem().c_str(), current) && !current) {
      std::string error;
      doc_ = EffectDocument::open(f, error);
      effect_message_ = error;
      fields_.forget_errors();
    }
  }
  if (!doc_) return;
  ImGui::Separator();
  if (ImGui::Button("Save (the level restarts with it)")) {
    try {
      doc_->save();
      effect_message_ = "saved " + fs::path(doc_->path()).filename().string();
    } catch (const InputError& e) {
      effect_message_ = e.what();
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Undo")) doc_->undo();
  ImGui::SameLine();
  if (ImGui::Button("Redo")) doc_->redo();
  if (doc_->dirty()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "unsaved edits");
  if (!effect_message_.empty()) ImGui::TextWrapped("%s", effect_message_.c_str());
  fields_.draw(*doc_);
}

}  // namespace arc
