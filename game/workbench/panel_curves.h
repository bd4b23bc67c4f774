// game/workbench/panel_curves.h — keyframe editors for effect curves (ImGui draw lists).
//
// A value curve (alpha, size, burn) is a graph over the particle's life, t in [0, 1] across and
// the value up; a colour curve is a gradient strip with its keys as markers under it. Drag a
// key to move it (t stays between its neighbours, the value in the field's range), double-click
// to add one, right-click a key to remove it; the selected key can be typed in below. The
// editors only change the key list; the panel writes it to the document.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace arc {

struct GraphKey {
  double t = 0.0;
  double value = 0.0;
};
struct ColourKey {
  double t = 0.0;
  std::array<double, 3> rgb{1.0, 1.0, 1.0};
};

// What an editor did this frame: changed the keys, and whether a drag is still held (the panel
// folds the edits of one drag into one undo step when it ends).
struct CurveEdit {
  bool changed = false;
  bool active = false;
};

class CurveEditors {
 public:
  CurveEdit value_curve(const std::string& id, std::vector<GraphKey>& keys, double lo, double hi);
  CurveEdit colour_curve(const std::string& id, std::vector<ColourKey>& keys, double hi);

 private:
  // The clicks both editors share: left on a key takes it, right on a key removes it (one stays),
  // a double click off the keys inserts `fresh` at its time.
  template <class Key>
  void click_keys(const std::string& id, std::vector<Key>& keys, int under, bool hovered, const Key& fresh,
                  CurveEdit& edit);

  std::string drag_id_;   // the editor whose key is held
  int drag_key_ = -1;
  double drag_top_ = 1.0; // the graph's top value, fixed while a key is held
  std::string selected_id_;
  int selected_key_ = -1;
};

}  // namespace arc
