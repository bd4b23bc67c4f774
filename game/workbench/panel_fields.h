// game/workbench/panel_fields.h — the panel's editor of every field of an effect file (ImGui).
//
// Walks the document's blocks (root, clusters, each cluster's animation, emitter, particles
// and curves) and gives each key of particles/effect_schema.h the widget its kind wants, over
// the range the loader accepts: sliders for short ranges and drags for long ones, combos for
// enumerations, a sprite picker with thumbnails, keyframe graphs for alpha, size and burn and a
// gradient strip for colour. Clusters can be added, duplicated, removed and reordered.
//
// Every change goes through EffectDocument::set/insert/remove/move, i.e. through the loader: a
// refused value leaves the document as it was and its one-line message is shown under the
// field until an edit of that field is accepted. The edits of one drag (a slider, a key of a
// curve) are folded into one undo step when the drag ends: undone, then set once to the final
// value (EffectDocument::drag() would also merge a second drag of the same field into the
// first, so the panel ends each drag itself). Keys that do nothing in the cluster as it stands
// (effect_field_applies: another animation type or emitter shape) are hidden unless the file
// has them; absent keys show their default, greyed.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "game/workbench/effect_document.h"
#include "game/workbench/panel_curves.h"

namespace arc {

class EffectPanel {
 public:
  // GL names of the sprite thumbnails, one per kSpriteNames entry (0: a text button instead).
  void set_sprite_thumbnails(std::vector<uint32_t> gl_names) { thumbnails_ = std::move(gl_names); }
  void draw(EffectDocument& doc);
  void forget_errors() { errors_.clear(); }  // another document was opened

 private:
  void draw_block(EffectDocument& doc, const std::string& pointer, EffectBlock block);
  void draw_clusters(EffectDocument& doc);
  void draw_field(EffectDocument& doc, const std::string& pointer, const EffectField& f);
  bool draw_value(EffectDocument& doc, const std::string& pointer, const EffectField& f, nlohmann::json& v);
  // Applies one edit; `active`: a drag is still held (see the header).
  void commit(EffectDocument& doc, const std::string& pointer, const nlohmann::json& value, bool active);
  void finish_drag(EffectDocument& doc);
  void show_result(const std::string& pointer, const EditResult& r);

  std::vector<uint32_t> thumbnails_;
  std::map<std::string, std::string> errors_;  // by pointer: the loader's message for a refused edit
  CurveEditors curves_;
  std::string drag_pointer_;  // the field a held drag edits
  int drag_edits_ = 0;        // accepted edits of that drag so far
  bool drag_seen_ = false;    // the held drag's field was drawn this frame
};

}  // namespace arc
