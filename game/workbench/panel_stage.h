// game/workbench/panel_stage.h — the workbench panel's stage and time sections (ImGui).
//
// The effect list (assets/effects/, switched here), the backdrop, and the timeline: play and
// pause, speed 0.1×–4×, one tick back or forwards, the loop period and a scrub slider over it.
#pragma once
#include <string>
#include <vector>

#include "game/workbench/workbench_stage.h"

namespace arc {

// Draws the effect combo; returns the index chosen this frame, or −1.
int draw_effect_list(const std::vector<std::string>& names, int current);
void draw_backdrop_section(WorkbenchStage& stage);
void draw_time_section(WorkbenchStage& stage);

}  // namespace arc
