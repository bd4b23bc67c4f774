// The panel's field editor (see the header).
#include "game/workbench/panel_fields.h"

#include <algorithm>
#include <cstdint>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "particles/sprites.h"

namespace arc {
namespace {

using json = nlohmann::json;

const ImVec4 kRefused(1.0f, 0.45f, 0.4f, 1.0f);

json at_or(const json& j, const std::string& pointer, const json& fallback) {
  const json::json_pointer p(pointer);
  return j.contains(p) ? j.at(p) : fallback;
}

// A short range is a slider; a long one (metres up to 1e6) a drag that moves with the value.
bool number_widget(const char* label, double& v, const EffectField& f, bool integer) {
  const bool slider = f.max - f.min <= 100.0;
  if (integer) {
    int i = int(v);
    const int lo = int(f.min), hi = int(std::min(f.max, 1e9));
    const bool changed = slider ? ImGui::SliderInt(label, &i, lo, hi) : ImGui::DragInt(label, &i, 1.0f, lo, hi);
    v = i;
    return changed;
  }
  if (slider) return ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &f.min, &f.max, "%.3f");
  const float speed = float(std::max(0.01, std::abs(v) * 0.01));
  return ImGui::DragScalar(label, ImGuiDataType_Double, &v, speed, &f.min, &f.max, "%.3f");
}

std::vector<GraphKey> curve_keys(const json& v) {
  if (v.is_number()) return {{0.0, v.get<double>()}, {1.0, v.get<double>()}};
  std::vector<GraphKey> keys;
  for (const json& k : v)
    if (k.is_array() && k.size() == 2 && k[0].is_number() && k[1].is_number()) keys.push_back({k[0], k[1]});
  return keys;
}

std::vector<ColourKey> colour_keys(const json& v) {
  std::vector<ColourKey> keys;
  for (const json& k : v)
    if (k.is_array() && k.size() == 2 && k[0].is_number() && k[1].is_array() && k[1].size() == 3)
      keys.push_back({k[0], {k[1][0].get<double>(), k[1][1].get<double>(), k[1][2].get<double>()}});
  return keys;
}

// Rounded so a dragged key writes "0.35", not seventeen digits.
double tidy(double v) { return std::round(v * 1000.0) / 1000.0; }

}  // namespace

void EffectPanel::draw(EffectDocument& doc) {
  drag_seen_ = false;
  ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  draw_block(doc, "", EffectBlock::Root);
  draw_clusters(doc);
  ImGui::PopItemWidth();
  if (!drag_pointer_.empty() && !drag_seen_) finish_drag(doc);
}

void EffectPanel::show_result(const std::string& pointer, const EditResult& r) {
  if (r.ok) errors_.erase(pointer);
  else errors_[pointer] = r.message;
}

void EffectPanel::commit(EffectDocument& doc, const std::string& pointer, const json& value, bool active) {
  if (drag_pointer_ != pointer) finish_drag(doc);
  const EditResult r = doc.set(pointer, value);
  show_result(pointer, r);
  if (active) {
    drag_pointer_ = pointer;
    drag_seen_ = true;
    if (r.ok) ++drag_edits_;
  } else if (drag_pointer_ == pointer) {
    if (r.ok) ++drag_edits_;
    finish_drag(doc);
  }
}

// One drag, one undo step: back to before it, then its final value as a single edit.
void EffectPanel::finish_drag(EffectDocument& doc) {
  const std::string pointer = drag_pointer_;
  const int edits = drag_edits_;
  drag_pointer_.clear();
  drag_edits_ = 0;
  if (edits < 2) return;
  const json final_value = at_or(doc.json(), pointer, json());
  for (int i = 0; i < edits; ++i) doc.undo();
  show_result(pointer, doc.set(pointer, final_value));
}

void EffectPanel::draw_block(EffectDocument& doc, const std::string& pointer, EffectBlock block) {
  const json& root = doc.json();
  const json block_json = at_or(root, pointer, json::object());
  json cluster_json = json::object();
  if (block != EffectBlock::Root) {
    const size_t cut = pointer.find('/', std::string("/clusters/").size());
    cluster_json = at_or(root, pointer.substr(0, cut), json::object());
  }
  for (const EffectField* f : effect_fields(block)) {
    if (f->kind == FieldKind::ObjectList) continue;  // the clusters: draw_clusters
    const bool present = block_json.is_object() && block_json.contains(f->key);
    if (!present && !effect_field_applies(*f, cluster_json)) continue;
    const std::string child = pointer + "/" + f->key;
    if (f->kind == FieldKind::Object) {
      if (ImGui::TreeNodeEx(child.c_str(), ImGuiTreeNodeFlags_DefaultOpen, "%s", f->key)) {
        EffectBlock sub;
        if (effect_block_at(child, sub)) draw_block(doc, child, sub);
        ImGui::TreePop();
      }
      continue;
    }
    draw_field(doc, child, *f);
  }
}

void EffectPanel::draw_field(EffectDocument& doc, const std::string& pointer, const EffectField& f) {
  const json::json_pointer jp(pointer);
  const bool present = doc.json().contains(jp);
  json v = present ? doc.json().at(jp) : f.fallback;
  ImGui::PushID(pointer.c_str());
  if (!present) ImGui::PushStyleVar(ImGuiStyleVar_Alpha, ImGui::GetStyle().Alpha * 0.6f);
  const bool changed = draw_value(doc, pointer, f, v);
  const bool active = ImGui::IsItemActive() || (drag_pointer_ == pointer && ImGui::IsMouseDown(ImGuiMouseButton_Left));
  if (ImGui::IsItemHovered()) {
    std::string tip = std::string(f.key) + (*f.unit ? std::string(" (") + f.unit + ")" : "");
    if (f.max > f.min) tip += "\nallowed: [" + json(f.min).dump() + ", " + json(f.max).dump() + "]";
    if (*f.applies) tip += std::string("\n") + f.applies;
    if (!present) tip += "\nnot in the file: the default";
    ImGui::SetTooltip("%s", tip.c_str());
  }
  if (!present) ImGui::PopStyleVar();
  if (active && drag_pointer_ == pointer) drag_seen_ = true;
  if (changed) commit(doc, pointer, v, active);
  if (auto it = errors_.find(pointer); it != errors_.end()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kRefused, "%s", it->second.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::PopID();
}

// Long: one case per field kind, each a few lines; splitting them would scatter the mapping.
bool EffectPanel::draw_value(EffectDocument& doc, const std::string& pointer, const EffectField& f, json& v) {
  std::string label = f.key;
  if (*f.unit) label += std::string(" (") + f.unit + ")";
  switch (f.kind) {
    case FieldKind::Number:
    case FieldKind::Integer: {
      double x = v.is_number() ? v.get<double>() : f.min;
      if (!number_widget(label.c_str(), x, f, f.kind == FieldKind::Integer)) return false;
      v = f.kind == FieldKind::Integer ? json(int64_t(x)) : json(x);
      return true;
    }
    case FieldKind::Enum: {
      const std::string cur = v.is_string() ? v.get<std::string>() : "";
      bool changed = false;
      if (ImGui::BeginCombo(label.c_str(), cur.c_str())) {
        for (const char* c : f.choices)
          if (ImGui::Selectable(c, cur == c)) v = c, changed = cur != c;
        ImGui::EndCombo();
      }
      return changed;
    }
    case FieldKind::String: {
      std::string s = v.is_string() ? v.get<std::string>() : "";
      ImGui::InputText(label.c_str(), &s);
      if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
      v = s;
      return true;
    }
    case FieldKind::Sprite: {
      const std::string cur = v.is_string() ? v.get<std::string>() : "";
      bool changed = false;
      for (size_t i = 0; i < kSpriteNames.size(); ++i) {
        const std::string name(kSpriteNames[i]);
        ImGui::PushID(int(i));
        if (i > 0) ImGui::SameLine();
        const bool sel = name == cur;
        ImGui::PushStyleColor(ImGuiCol_Button, sel ? ImVec4(0.9f, 0.7f, 0.2f, 1.0f) : ImVec4(0.2f, 0.22f, 0.28f, 1.0f));
        const bool hit = i < thumbnails_.size() && thumbnails_[i]
                             ? ImGui::ImageButton(ImTextureID(intptr_t(thumbnails_[i])), ImVec2(30, 30))
                             : ImGui::Button(name.c_str());
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", name.c_str());
        if (hit && !sel) v = name, changed = true;
        ImGui::PopID();
      }
      ImGui::SameLine();
      ImGui::Text("%s", cur.c_str());
      return changed;
    }
    case FieldKind::Vec3: {
      double xyz[3] = {0, 0, 0};
      for (int i = 0; v.is_array() && i < 3 && i < int(v.size()); ++i) xyz[i] = v[size_t(i)].is_number() ? v[size_t(i)].get<double>() : 0.0;
      if (!ImGui::DragScalarN(label.c_str(), ImGuiDataType_Double, xyz, 3, 0.05f, &f.min, &f.max, "%.3f")) return false;
      v = json::array({xyz[0], xyz[1], xyz[2]});
      return true;
    }
    case FieldKind::Range: {
      double mm[2] = {0, 0};
      if (v.is_number()) mm[0] = mm[1] = v.get<double>();
      else if (v.is_array() && v.size() == 2) mm[0] = v[0].get<double>(), mm[1] = v[1].get<double>();
      const float speed = float(std::max(0.01, std::abs(mm[1]) * 0.01));
      if (!ImGui::DragScalarN(label.c_str(), ImGuiDataType_Double, mm, 2, speed, &f.min, &f.max, "%.3f")) return false;
      v = mm[0] == mm[1] && !v.is_array() ? json(mm[0]) : json::array({mm[0], mm[1]});
      return true;
    }
    case FieldKind::Curve: {
      ImGui::TextUnformatted(label.c_str());
      std::vector<GraphKey> keys = curve_keys(v);
      const CurveEdit e = curves_.value_curve(pointer, keys, f.min, f.max);
      if (e.active && drag_pointer_ == pointer) drag_seen_ = true;
      if (!e.changed) return false;
      json out = json::array();
      for (const GraphKey& k : keys) out.push_back(json::array({tidy(k.t), tidy(k.value)}));
      v = out;
      if (e.active) commit(doc, pointer, v, true);
      return !e.active;
    }
    case FieldKind::ColourCurve: {
      ImGui::TextUnformatted(label.c_str());
      std::vector<ColourKey> keys = colour_keys(v);
      const CurveEdit e = curves_.colour_curve(pointer, keys, f.max);
      if (e.active && drag_pointer_ == pointer) drag_seen_ = true;
      if (!e.changed) return false;
      json out = json::array();
      for (const ColourKey& k : keys)
        out.push_back(json::array({tidy(k.t), json::array({tidy(k.rgb[0]), tidy(k.rgb[1]), tidy(k.rgb[2])})}));
      v = out;
      if (e.active) commit(doc, pointer, v, true);
      return !e.active;
    }
    case FieldKind::Vec3List:
      ImGui::Text("%s: %zu vertices (edit in the file)", label.c_str(), v.is_array() ? v.size() : size_t(0));
      return false;
    case FieldKind::Object:
    case FieldKind::ObjectList:
      return false;
  }
  return false;
}

// The cluster list with its per-cluster buttons and the add button.
void EffectPanel::draw_clusters(EffectDocument& doc) {
  const json clusters = at_or(doc.json(), "/clusters", json::array());
  ImGui::Separator();
  ImGui::Text("clusters (%zu)", clusters.size());
  if (errors_.count("/clusters")) ImGui::TextColored(kRefused, "%s", errors_["/clusters"].c_str());
  for (size_t i = 0; i < clusters.size(); ++i) {
    const std::string pointer = "/clusters/" + std::to_string(i);
    const std::string name = clusters[i].value("name", "cluster " + std::to_string(i));
    ImGui::PushID(int(i));
    if (i == 0) ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    const bool open = ImGui::TreeNodeEx("##cluster", ImGuiTreeNodeFlags_AllowItemOverlap, "%zu  %s", i, name.c_str());
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 150.0f);
    EditResult r;
    bool acted = false;
    if (ImGui::SmallButton("up") && i > 0) r = doc.move("/clusters", i, i - 1), acted = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("down") && i + 1 < clusters.size()) r = doc.move("/clusters", i, i + 1), acted = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("dup")) r = doc.duplicate(pointer), acted = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("del")) r = doc.remove(pointer), acted = true;
    if (acted) show_result("/clusters", r);
    if (open) {
      if (!acted) draw_block(doc, pointer, EffectBlock::Cluster);
      ImGui::TreePop();
    }
    ImGui::PopID();
    if (acted) break;  // indices moved: the rest is drawn next frame
  }
  if (ImGui::Button("add cluster")) {
    const json fresh = {{"name", "new"},
                        {"sprite", "blob"},
                        {"animation", {{"type", "linear"}}},
                        {"emitter", {{"shape", "sphere"}, {"radius", 1}, {"rate", 40}}},
                        {"particles", {{"lifetime", 1.0}, {"speed", json::array({1, 3})}}}};
    show_result("/clusters", doc.insert("/clusters", clusters.size(), fresh));
  }
}

}  // namespace arc
