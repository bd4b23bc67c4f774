// Keyframe editors for value and colour curves (see the header).
#include "game/workbench/panel_curves.h"

#include <algorithm>
#include <cmath>
#include <imgui.h>

namespace arc {
namespace {

constexpr float kGrab = 6.0f;         // px: how near the cursor must be to take a key
constexpr double kMinGap = 0.001;     // keys' t stay this far apart, rising

ImU32 colour_u32(const std::array<double, 3>& rgb) {
  auto c = [](double v) { return float(std::clamp(v, 0.0, 1.0)); };
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c(rgb[0]), c(rgb[1]), c(rgb[2]), 1.0f));
}

// The t a held key may take: between its neighbours.
template <typename Key>
double clamp_t(const std::vector<Key>& keys, int i, double t) {
  const double lo = i > 0 ? keys[size_t(i - 1)].t + kMinGap : 0.0;
  const double hi = i + 1 < int(keys.size()) ? keys[size_t(i + 1)].t - kMinGap : 1.0;
  return std::clamp(t, lo, std::max(lo, hi));
}

// Index where a key at t goes, keeping t rising.
template <typename Key>
size_t insert_at(const std::vector<Key>& keys, double t) {
  size_t i = 0;
  while (i < keys.size() && keys[i].t < t) ++i;
  return i;
}

double value_at(const std::vector<GraphKey>& keys, double t) {
  if (keys.empty()) return 0.0;
  if (t <= keys.front().t) return keys.front().value;
  for (size_t i = 1; i < keys.size(); ++i)
    if (t <= keys[i].t) {
      const double f = (t - keys[i - 1].t) / std::max(1e-9, keys[i].t - keys[i - 1].t);
      return keys[i - 1].value + (keys[i].value - keys[i - 1].value) * f;
    }
  return keys.back().value;
}

std::array<double, 3> colour_at(const std::vector<ColourKey>& keys, double t) {
  if (keys.empty()) return {1, 1, 1};
  if (t <= keys.front().t) return keys.front().rgb;
  for (size_t i = 1; i < keys.size(); ++i)
    if (t <= keys[i].t) {
      const double f = (t - keys[i - 1].t) / std::max(1e-9, keys[i].t - keys[i - 1].t);
      std::array<double, 3> c{};
      for (int k = 0; k < 3; ++k) c[size_t(k)] = keys[i - 1].rgb[size_t(k)] * (1 - f) + keys[i].rgb[size_t(k)] * f;
      return c;
    }
  return keys.back().rgb;
}

// The key under the cursor (by x only when `x_only`), or −1.
template <typename Key, typename Pos>
int key_under(const std::vector<Key>& keys, Pos pos, ImVec2 mouse) {
  for (int i = 0; i < int(keys.size()); ++i) {
    const ImVec2 p = pos(keys[size_t(i)]);
    if (std::abs(p.x - mouse.x) <= kGrab && std::abs(p.y - mouse.y) <= kGrab) return i;
  }
  return -1;
}

}  // namespace

template <class Key>
void CurveEditors::click_keys(const std::string& id, std::vector<Key>& keys, int under, bool hovered, const Key& fresh,
                              CurveEdit& edit) {
  if (under >= 0 && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    drag_id_ = id, drag_key_ = under, selected_id_ = id, selected_key_ = under;
  } else if (under >= 0 && ImGui::IsMouseClicked(ImGuiMouseButton_Right) && keys.size() > 1) {
    keys.erase(keys.begin() + under);
    edit.changed = true;
    selected_key_ = -1;
  } else if (under < 0 && hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    const size_t at = insert_at(keys, fresh.t);
    keys.insert(keys.begin() + long(at), fresh);
    edit.changed = true;
    selected_id_ = id, selected_key_ = int(at);
  }
}

// Drawing, hit-testing and the three gestures of one editor, kept together.
CurveEdit CurveEditors::value_curve(const std::string& id, std::vector<GraphKey>& keys, double lo, double hi) {
  CurveEdit edit;
  const bool holding = drag_id_ == id && drag_key_ >= 0;
  if (!holding) {  // the graph's height: the range, or for wide ranges a little above the keys
    double top = 0.0;
    for (const GraphKey& k : keys) top = std::max(top, k.value);
    drag_top_ = hi <= 1.0 ? hi : std::min(hi, std::max(1.0, std::ceil(top * 1.5)));
  }
  const double top = drag_top_ > lo ? drag_top_ : lo + 1.0;
  const ImVec2 size(ImGui::GetContentRegionAvail().x, 56.0f);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id.c_str(), size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  auto pos = [&](const GraphKey& k) {
    return ImVec2(o.x + float(k.t) * size.x, o.y + size.y - float((k.value - lo) / (top - lo)) * size.y);
  };
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const double mt = std::clamp(double((mouse.x - o.x) / size.x), 0.0, 1.0);
  const double mv = std::clamp(lo + double((o.y + size.y - mouse.y) / size.y) * (top - lo), lo, hi);
  const int under = hovered ? key_under(keys, pos, mouse) : -1;
  click_keys(id, keys, under, hovered, GraphKey{mt, mv}, edit);
  if (drag_id_ == id && drag_key_ >= 0) {
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      drag_key_ = -1;
    } else if (drag_key_ < int(keys.size())) {
      GraphKey& k = keys[size_t(drag_key_)];
      const GraphKey moved{clamp_t(keys, drag_key_, mt), mv};
      if (moved.t != k.t || moved.value != k.value) k = moved, edit.changed = true;
      edit.active = true;
    }
  }
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(20, 24, 32, 255));
  for (int g = 1; g < 4; ++g) {
    const float x = o.x + size.x * float(g) / 4.0f, y = o.y + size.y * float(g) / 4.0f;
    dl->AddLine(ImVec2(x, o.y), ImVec2(x, o.y + size.y), IM_COL32(50, 56, 70, 255));
    dl->AddLine(ImVec2(o.x, y), ImVec2(o.x + size.x, y), IM_COL32(50, 56, 70, 255));
  }
  ImVec2 prev = pos(GraphKey{0.0, value_at(keys, 0.0)});
  for (int s = 1; s <= 64; ++s) {
    const double t = s / 64.0;
    const ImVec2 p = pos(GraphKey{t, value_at(keys, t)});
    dl->AddLine(prev, p, IM_COL32(120, 200, 255, 255), 2.0f);
    prev = p;
  }
  for (int i = 0; i < int(keys.size()); ++i) {
    const bool sel = selected_id_ == id && selected_key_ == i;
    dl->AddCircleFilled(pos(keys[size_t(i)]), sel ? 5.0f : 4.0f, sel ? IM_COL32(255, 220, 90, 255) : IM_COL32(230, 230, 230, 255));
  }
  char top_label[32];
  std::snprintf(top_label, sizeof top_label, "%g", top);
  dl->AddText(ImVec2(o.x + 3, o.y + 1), IM_COL32(140, 150, 170, 255), top_label);
  if (selected_id_ == id && selected_key_ >= 0 && selected_key_ < int(keys.size())) {
    GraphKey& k = keys[size_t(selected_key_)];
    double tv[2] = {k.t, k.value};
    if (ImGui::DragScalarN(("key##" + id).c_str(), ImGuiDataType_Double, tv, 2, 0.005f)) {
      k.t = clamp_t(keys, selected_key_, tv[0]);
      k.value = tv[1];  // out of range is the validator's to refuse
      edit.changed = true;
    }
    edit.active = edit.active || ImGui::IsItemActive();
  }
  return edit;
}

// As value_curve, for the colour strip and its colour picker.
CurveEdit CurveEditors::colour_curve(const std::string& id, std::vector<ColourKey>& keys, double hi) {
  CurveEdit edit;
  const ImVec2 size(ImGui::GetContentRegionAvail().x, 30.0f);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float marker_y = o.y + size.y - 5.0f;
  ImGui::InvisibleButton(id.c_str(), size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  auto pos = [&](const ColourKey& k) { return ImVec2(o.x + float(k.t) * size.x, marker_y); };
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const double mt = std::clamp(double((mouse.x - o.x) / size.x), 0.0, 1.0);
  int under = -1;
  for (int i = 0; hovered && i < int(keys.size()); ++i)
    if (std::abs(pos(keys[size_t(i)]).x - mouse.x) <= kGrab && mouse.y >= marker_y - kGrab) under = i;
  click_keys(id, keys, under, hovered, ColourKey{mt, colour_at(keys, mt)}, edit);
  if (drag_id_ == id && drag_key_ >= 0) {
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      drag_key_ = -1;
    } else if (drag_key_ < int(keys.size())) {
      const double t = clamp_t(keys, drag_key_, mt);
      if (t != keys[size_t(drag_key_)].t) keys[size_t(drag_key_)].t = t, edit.changed = true;
      edit.active = true;
    }
  }
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float strip_bottom = o.y + size.y - 10.0f;
  for (int s = 0; s < 48; ++s) {
    const double t0 = s / 48.0, t1 = (s + 1) / 48.0;
    const ImU32 c0 = colour_u32(colour_at(keys, t0)), c1 = colour_u32(colour_at(keys, t1));
    dl->AddRectFilledMultiColor(ImVec2(o.x + float(t0) * size.x, o.y), ImVec2(o.x + float(t1) * size.x, strip_bottom),
                                c0, c1, c1, c0);
  }
  for (int i = 0; i < int(keys.size()); ++i) {
    const ImVec2 p = pos(keys[size_t(i)]);
    const bool sel = selected_id_ == id && selected_key_ == i;
    dl->AddTriangleFilled(ImVec2(p.x, strip_bottom), ImVec2(p.x - 5, p.y + 5), ImVec2(p.x + 5, p.y + 5),
                          sel ? IM_COL32(255, 220, 90, 255) : IM_COL32(230, 230, 230, 255));
  }
  if (selected_id_ == id && selected_key_ >= 0 && selected_key_ < int(keys.size())) {
    ColourKey& k = keys[size_t(selected_key_)];
    float rgb[3] = {float(k.rgb[0]), float(k.rgb[1]), float(k.rgb[2])};
    if (ImGui::ColorEdit3(("key colour##" + id).c_str(), rgb, ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_Float)) {
      for (int c = 0; c < 3; ++c) k.rgb[size_t(c)] = std::clamp(double(rgb[c]), 0.0, hi * 2.0);
      edit.changed = true;
    }
    edit.active = edit.active || ImGui::IsItemActive();
  }
  return edit;
}

}  // namespace arc
