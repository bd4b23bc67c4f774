// The workbench's stats overlay (see the header).
#include "game/workbench/stats_overlay.h"

#include <algorithm>
#include <cstdio>
#include <imgui.h>

namespace arc {

void StatsOverlay::record_frame(double seconds) {
  frame_ms_[next_] = float(seconds * 1000.0);
  next_ = (next_ + 1) % kFrames;
  filled_ = std::min(filled_ + 1, kFrames);
}

void StatsOverlay::draw(const StageFigures& stage, const FrameStats& frame, int width) const {
  ImGui::SetNextWindowPos(ImVec2(float(width) - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.65f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (!ImGui::Begin("Stats", nullptr, flags)) {
    ImGui::End();
    return;
  }
  for (size_t i = 0; i < stage.cluster_names.size() && i < stage.live_per_cluster.size(); ++i)
    ImGui::Text("%-16s %7u live", stage.cluster_names[i].c_str(), stage.live_per_cluster[i]);
  ImGui::Separator();
  ImGui::Text("drawn %d   soft-shaded %d", frame.particles_drawn, frame.soft_shaded);
  if (frame.particle_fragments >= 0) {
    const double layers = stage.scene_pixels > 0 ? double(frame.particle_fragments) / stage.scene_pixels : 0.0;
    ImGui::Text("blended pixels %lld (%.2f screens)", frame.particle_fragments, layers);
  } else {
    ImGui::TextDisabled(frame.particles_drawn == 0 ? "blended pixels 0 (nothing drawn)"
                                                   : "blended pixels: no occlusion query on this driver");
  }
  if (frame.particle_pass_gpu_ms >= 0)
    ImGui::Text("particle pass %.2f ms CPU, %.2f ms GPU", frame.particle_cpu_ms, frame.particle_pass_gpu_ms);
  else
    ImGui::Text("particle pass %.2f ms CPU", frame.particle_cpu_ms);
  const float share = stage.budget > 0 ? float(stage.live) / float(stage.budget) : 0.0f;
  char label[64];
  std::snprintf(label, sizeof label, "%u / %u", stage.live, stage.budget);
  ImGui::ProgressBar(share, ImVec2(260.0f, 0.0f), label);
  ImGui::SameLine();
  ImGui::TextUnformatted("budget");
  // Oldest first: the ring from the next slot on.
  std::array<float, kFrames> ordered{};
  const size_t start = filled_ < kFrames ? 0 : next_;
  for (size_t i = 0; i < filled_; ++i) ordered[i] = frame_ms_[(start + i) % kFrames];
  const float worst = filled_ ? *std::max_element(ordered.begin(), ordered.begin() + long(filled_)) : 0.0f;
  std::snprintf(label, sizeof label, "frame ms (max %.1f)", worst);
  ImGui::PlotLines("##frames", ordered.data(), int(filled_), 0, label, 0.0f, std::max(33.4f, worst),
                   ImVec2(260.0f, 60.0f));
  ImGui::End();
}

}  // namespace arc
