// The panel's stage and time sections (see the header).
#include "game/workbench/panel_stage.h"

#include <cstdio>
#include <imgui.h>

namespace arc {

int draw_effect_list(const std::vector<std::string>& names, int current) {
  int chosen = -1;
  const char* preview = current >= 0 && current < int(names.size()) ? names[size_t(current)].c_str() : "";
  if (ImGui::BeginCombo("effect", preview)) {
    for (int i = 0; i < int(names.size()); ++i)
      if (ImGui::Selectable(names[size_t(i)].c_str(), i == current)) chosen = i;
    ImGui::EndCombo();
  }
  return chosen;
}

void draw_backdrop_section(WorkbenchStage& stage) {
  const Backdrop b = stage.backdrop();
  const std::vector<StageModel>& ships = stage.ship_models();
  // Space, each ship, the wall, then a circling flight per ship.
  std::vector<std::string> labels{"empty space"};
  std::vector<Backdrop> choices{{BackdropKind::Space, 0}};
  for (size_t i = 0; i < ships.size(); ++i) {
    labels.push_back(ships[i].name);
    choices.push_back({BackdropKind::Model, i});
  }
  labels.push_back("wall");
  choices.push_back({BackdropKind::Wall, 0});
  for (size_t i = 0; i < ships.size(); ++i) {
    labels.push_back("attached to " + ships[i].name + " flying a circle");
    choices.push_back({BackdropKind::Circling, i});
  }
  size_t current = 0;
  for (size_t i = 0; i < choices.size(); ++i)
    if (choices[i].kind == b.kind && (b.kind == BackdropKind::Space || b.kind == BackdropKind::Wall ||
                                      choices[i].model == b.model))
      current = i;
  if (ImGui::BeginCombo("backdrop", labels[current].c_str())) {
    for (size_t i = 0; i < choices.size(); ++i)
      if (ImGui::Selectable(labels[i].c_str(), i == current)) stage.set_backdrop({choices[i].kind, choices[i].model, b.at_stern});
    ImGui::EndCombo();
  }
  if (b.kind != BackdropKind::Circling) return;
  bool stern = b.at_stern;
  if (ImGui::Checkbox("effect at the stern", &stern)) stage.set_backdrop({b.kind, b.model, stern});
}

void draw_time_section(WorkbenchStage& stage) {
  if (ImGui::Button(stage.playing() ? "Pause" : "Play", ImVec2(60, 0))) stage.set_playing(!stage.playing());
  ImGui::SameLine();
  if (ImGui::Button("<1")) stage.step_by(-1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("one tick back (Left)");
  ImGui::SameLine();
  if (ImGui::Button("1>")) stage.step_by(1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("one tick forwards (Right)");
  ImGui::SameLine();
  if (ImGui::Button("|<")) stage.scrub(0);
  float speed = float(stage.speed());
  if (ImGui::SliderFloat("speed", &speed, 0.1f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) stage.set_speed(speed);
  float loop = float(stage.loop_seconds());
  if (ImGui::DragFloat("loop (s)", &loop, 0.02f, 0.1f, 60.0f, "%.2f s", ImGuiSliderFlags_AlwaysClamp))
    stage.set_loop_seconds(loop);
  bool ends = true;
  const double own = stage.effect_seconds(&ends);
  ImGui::SameLine();
  if (ImGui::SmallButton("fit")) stage.set_loop_seconds(own + 0.25);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(ends ? "loop over the effect's life: %.2f s" : "it runs until stopped: loop %.2f s of it", own);
  int tick = int(stage.tick());
  char label[64];
  std::snprintf(label, sizeof label, "tick %%d  (%.3f s)", double(stage.tick()) * stage.tick_seconds());
  if (ImGui::SliderInt("time", &tick, 0, int(stage.loop_ticks()), label, ImGuiSliderFlags_AlwaysClamp)) {
    stage.set_playing(false);
    stage.scrub(uint64_t(tick));
  }
}

}  // namespace arc
