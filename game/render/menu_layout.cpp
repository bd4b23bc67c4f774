// Menu screens as HUD quads and text: a dimmed backdrop, a centred panel, title, text, items.
#include "game/render/menu_layout.h"

#include <algorithm>

#include "game/render/hud_draw.h"

namespace arc {
namespace {

constexpr double kGlyph = 7.0;  // pixels per character at text scale 1 (gfx/hud_font)
constexpr double kPanelWidth = 760.0;
const glm::vec4 kPanel{0.02f, 0.04f, 0.09f, 0.78f};
const glm::vec4 kSelected{0.3f, 0.6f, 1.0f, 0.35f};
const glm::vec4 kDim{0.75f, 0.85f, 0.95f, 0.9f};

void centred(HudLayer& h, double cx, double y, double scale, const glm::vec4& c, const std::string& s) {
  text(h, cx - s.size() * kGlyph * scale * 0.5, y, scale, c, s);
}

// Lines of a paragraph wrapped to the panel, from `y`; returns the y below them.
double paragraph(HudLayer& h, const std::string& s, double left, double y, double width, double scale,
                 const glm::vec4& colour = kDim) {
  const size_t chars = size_t(std::max(8.0, width / (kGlyph * scale)));
  for (const std::string& l : wrap_text(s, chars, 12)) {
    text(h, left, y, scale, colour, l);
    y += 15 * scale;
  }
  return y;
}

}  // namespace

void layout_menu(const MenuPage& page, int width, int height, HudLayer& out, std::vector<HudBox>* item_boxes) {
  // Laid out on the 720-unit canvas, then scaled like the HUD.
  const double scale = hud_canvas_scale(std::max(height, 1));
  const double w = std::max(1.0, std::max(width, 1) / scale), hgt = std::max(1.0, std::max(height, 1) / scale);
  HudLayer h;
  quad(h, 0, 0, w, hgt, {0.0f, 0.0f, 0.03f, 0.35f});
  const double panel_w = std::min(kPanelWidth, w - 40), left = (w - panel_w) * 0.5, inner = panel_w - 48;
  const double top = std::max(20.0, hgt * 0.08);
  double y = top + 24;
  centred(h, w * 0.5, y, 3.0, page.title_tone > 0 ? kHudGreen : page.title_tone < 0 ? kHudRed : kHudWhite, page.title);
  y += 50;
  if (!page.subtitle.empty()) {
    centred(h, w * 0.5, y, 1.4, kHudYellow, page.subtitle);
    y += 30;
  }
  if (!page.paragraph.empty()) y = paragraph(h, page.paragraph, left + 24, y, inner, 1.2) + 12;
  for (const std::string& l : page.lines) {
    text(h, left + 48, y, 1.3, kHudWhite, l);
    y += 20;
  }
  if (!page.lines.empty()) y += 12;
  const double row = 28, item_scale = 1.5;
  std::vector<HudBox> boxes(page.items.size(), HudBox{-1, -1, -1, -1});
  const size_t first = size_t(std::max(page.first, 0));
  const size_t end = page.rows > 0 ? std::min(page.items.size(), first + size_t(page.rows)) : page.items.size();
  if (first > 0) centred(h, w * 0.5, y - 18, 1.0, kDim, "^ more ^");
  for (size_t i = first; i < end; ++i) {
    const bool sel = int(i) == page.selection;
    const HudBox box{left + 24, y - 6, left + panel_w - 24, y + row - 8};
    if (sel) quad(h, box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0, kSelected);
    text(h, left + 40, y, item_scale, sel ? kHudYellow : kHudWhite, page.items[i]);
    boxes[i] = {box.x0 * scale, box.y0 * scale, box.x1 * scale, box.y1 * scale};
    y += row;
  }
  if (end < page.items.size()) centred(h, w * 0.5, y - 6, 1.0, kDim, "v more v");
  y += 8;
  if (!page.message.empty()) y = paragraph(h, page.message, left + 24, y, inner, 1.1, kHudYellow) + 8;
  if (!page.hint.empty()) centred(h, w * 0.5, y, 1.0, kDim, page.hint);
  // The panel fits what is on it, so the demo behind shows below a short menu.
  h.quads.insert(h.quads.begin() + 1, HudQuad{float(left), float(top), float(panel_w), float(y + 28 - top), kPanel});
  scale_hud(h, scale);
  out.quads.insert(out.quads.end(), h.quads.begin(), h.quads.end());
  out.lines.insert(out.lines.end(), h.lines.begin(), h.lines.end());
  out.texts.insert(out.texts.end(), h.texts.begin(), h.texts.end());
  if (item_boxes) *item_boxes = std::move(boxes);
}

int menu_item_at(const std::vector<HudBox>& boxes, double x, double y) {
  for (size_t i = 0; i < boxes.size(); ++i)
    if (x >= boxes[i].x0 && x <= boxes[i].x1 && y >= boxes[i].y0 && y <= boxes[i].y1) return int(i);
  return -1;
}

}  // namespace arc
