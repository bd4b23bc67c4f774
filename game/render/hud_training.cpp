// game/render/hud_training.cpp — the training step's prompt with the bound keys filled in.
#include "game/render/hud_training.h"

#include <algorithm>
#include <vector>

#include "game/render/hud_draw.h"
#include "game/render/hud_layout.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kLineHeight = 13.0;  // the bitmap font's line at text scale 1
constexpr size_t kPromptLines = 4;
constexpr double kPad = 6.0;

std::string key_text(const std::string& action, const std::map<std::string, std::string>& key_names) {
  auto spaced = [](std::string s) {
    std::replace(s.begin(), s.end(), '_', ' ');
    return s;
  };
  const auto k = key_names.find(action);
  if (k == key_names.end() || k->second.empty() || k->second == "NONE") return "[no key: " + spaced(action) + "]";
  const std::string& key = k->second;
  if (key.rfind("MOUSE_", 0) == 0) return "[" + key.substr(6) + " MOUSE]";
  return "[" + spaced(key) + "]";
}

}  // namespace

std::string training_prompt(const std::string& prompt, const std::map<std::string, std::string>& key_names) {
  std::string out;
  for (size_t i = 0; i < prompt.size(); ++i) {
    const size_t end = prompt[i] == '{' ? prompt.find('}', i) : std::string::npos;
    if (end == std::string::npos) {
      out += prompt[i];
      continue;
    }
    out += key_text(prompt.substr(i + 1, end - i - 1), key_names);
    i = end;
  }
  return out;
}

bool training_prompt_shown(const World& w) {
  return w.training && size_t(w.training->step) < w.level.training.steps.size();
}

double hud_training_prompt(const World& w, const std::map<std::string, std::string>& key_names, double x0, double x1,
                           double y0, int width, HudLayer& h) {
  if (!training_prompt_shown(w)) return y0;
  const size_t step = size_t(w.training->step), steps = w.level.training.steps.size();
  const std::string prompt = training_prompt(w.level.training.steps[step].prompt, key_names);
  // Centred on the screen at twice the font's size where that leaves 36 characters a line, else
  // at its own size, centred where 40 fit, else across all the room there is.
  const double centre = width * 0.5, half = std::min(centre - x0, x1 - centre);
  double s = 1.0, left = x0, right = x1;
  if (2 * half >= 36 * kGlyphAdvance * 2.0) s = 2.0, left = centre - half, right = centre + half;
  else if (2 * half >= 40 * kGlyphAdvance) left = centre - half, right = centre + half;
  const size_t chars = size_t(std::max(8.0, (right - left - 2 * kPad) / (kGlyphAdvance * s)));
  const std::vector<std::string> lines = wrap_text(prompt, chars, kPromptLines);
  const std::string header = "TRAINING " + std::to_string(step + 1) + "/" + std::to_string(steps);
  size_t widest = header.size();
  for (const std::string& l : lines) widest = std::max(widest, size_t(double(l.size()) * s));
  const double mid = (left + right) * 0.5, box_w = double(widest) * kGlyphAdvance + 2 * kPad;
  const double line_h = kLineHeight * s + 3, box_h = kLineHeight + 4 + line_h * double(lines.size()) + 2 * kPad;
  quad(h, mid - box_w * 0.5, y0, box_w, box_h, kHudBack);
  text(h, mid - double(header.size()) * kGlyphAdvance * 0.5, y0 + kPad, 1.0, kHudYellow, header);
  double y = y0 + kPad + kLineHeight + 4;
  for (const std::string& l : lines) {
    text(h, mid - double(l.size()) * kGlyphAdvance * s * 0.5, y, s, kHudWhite, l);
    y += line_h;
  }
  return y0 + box_h;
}

}  // namespace arc
