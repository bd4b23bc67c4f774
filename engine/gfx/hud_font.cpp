// gfx/hud_font.cpp — HUD quads, lines and text as triangles over Dear ImGui's font atlas.
#include "gfx/hud_font.h"

#include <cmath>

#include <imgui.h>

namespace arc {

struct HudFont::Impl {
  ImFontAtlas atlas;
  ImFont* font = nullptr;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
};

HudFont::HudFont() : impl_(std::make_unique<Impl>()) {
  impl_->font = impl_->atlas.AddFontDefault();
  impl_->atlas.GetTexDataAsRGBA32(&impl_->pixels, &impl_->w, &impl_->h);
}
HudFont::~HudFont() = default;
int HudFont::width() const { return impl_->w; }
int HudFont::height() const { return impl_->h; }
const uint8_t* HudFont::pixels() const { return impl_->pixels; }
float HudFont::line_height() const { return impl_->font->FontSize; }

namespace {

void quad(std::vector<HudVertex>& out, const float (&px)[4][2], float u0, float v0, float u1, float v1, const glm::vec4& c) {
  const float uv[4][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
  for (int i : {0, 1, 2, 0, 2, 3}) out.push_back({px[i][0], px[i][1], uv[i][0], uv[i][1], c.r, c.g, c.b, c.a});
}

}  // namespace

void HudFont::build(const HudLayer& hud, std::vector<HudVertex>& out) const {
  ImVec2 white = impl_->atlas.TexUvWhitePixel;
  for (const HudQuad& q : hud.quads) {
    const float p[4][2] = {{q.x, q.y}, {q.x + q.w, q.y}, {q.x + q.w, q.y + q.h}, {q.x, q.y + q.h}};
    quad(out, p, white.x, white.y, white.x, white.y, q.color);
  }
  for (const HudLine& l : hud.lines) {
    float dx = l.x1 - l.x0, dy = l.y1 - l.y0;
    float len = std::sqrt(dx * dx + dy * dy);
    float nx = len > 1e-6f ? -dy / len : 0.0f, ny = len > 1e-6f ? dx / len : 1.0f;
    float hw = 0.5f * std::max(l.width, 1.0f);
    const float p[4][2] = {{l.x0 + nx * hw, l.y0 + ny * hw}, {l.x1 + nx * hw, l.y1 + ny * hw},
                           {l.x1 - nx * hw, l.y1 - ny * hw}, {l.x0 - nx * hw, l.y0 - ny * hw}};
    quad(out, p, white.x, white.y, white.x, white.y, l.color);
  }
  for (const HudText& t : hud.texts) {
    float s = t.scale > 0 ? t.scale : 1.0f;
    float x = t.x, y = t.y;
    for (unsigned char ch : t.text) {
      if (ch == '\n') {
        x = t.x;
        y += line_height() * s;
        continue;
      }
      const ImFontGlyph* g = impl_->font->FindGlyph(ImWchar(ch < 128 ? ch : '?'));
      if (!g) continue;
      if (g->Visible) {
        const float p[4][2] = {{x + g->X0 * s, y + g->Y0 * s}, {x + g->X1 * s, y + g->Y0 * s},
                               {x + g->X1 * s, y + g->Y1 * s}, {x + g->X0 * s, y + g->Y1 * s}};
        quad(out, p, g->U0, g->V0, g->U1, g->V1, t.color);
      }
      x += g->AdvanceX * s;
    }
  }
}

}  // namespace arc
