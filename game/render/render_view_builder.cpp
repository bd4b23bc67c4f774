#include "game/render/render_view_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "game/sim/simulation.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadarRange = 3000.0;
const glm::vec4 kHudGreen{0.45f, 1.0f, 0.6f, 0.9f};
const glm::vec4 kHudRed{1.0f, 0.35f, 0.3f, 0.95f};
const glm::vec4 kHudBlue{0.4f, 0.7f, 1.0f, 0.9f};
const glm::vec4 kHudYellow{1.0f, 0.85f, 0.3f, 0.9f};
const glm::vec4 kHudWhite{1.0f, 1.0f, 1.0f, 0.95f};
const glm::vec4 kHudBack{0.0f, 0.0f, 0.0f, 0.45f};

// Screen projection of the frame's camera, in pixels (origin top-left).
struct Projector {
  glm::dvec3 position;
  glm::dquat inverse;
  double focal, cx, cy, near_plane;
  glm::dvec3 to_view(const glm::dvec3& p) const { return inverse * (p - position); }
  bool project(const glm::dvec3& world, glm::dvec2& px, double* depth = nullptr) const {
    glm::dvec3 v = to_view(world);
    if (v.z > -near_plane) return false;
    px = {cx + v.x / -v.z * focal, cy - v.y / -v.z * focal};
    if (depth) *depth = -v.z;
    return true;
  }
};

glm::dvec3 lerp_pos(const glm::dvec3& a, const glm::dvec3& b, double t) { return a + (b - a) * t; }

void line(HudLayer& h, double x0, double y0, double x1, double y1, const glm::vec4& c, float width = 2.0f) {
  h.lines.push_back({float(x0), float(y0), float(x1), float(y1), width, c});
}
void quad(HudLayer& h, double x, double y, double w, double hh, const glm::vec4& c) {
  h.quads.push_back({float(x), float(y), float(w), float(hh), c});
}
void text(HudLayer& h, double x, double y, double scale, const glm::vec4& c, std::string s) {
  h.texts.push_back({float(x), float(y), float(scale), c, std::move(s)});
}

void bar(HudLayer& h, double x, double y, double w, double hh, double frac, const glm::vec4& c, const char* label) {
  frac = std::clamp(frac, 0.0, 1.0);
  quad(h, x, y, w, hh, kHudBack);
  quad(h, x + 1, y + 1, (w - 2) * frac, hh - 2, c);
  text(h, x, y - 16, 1.0, c, label);
}

void brackets(HudLayer& h, glm::dvec2 c, double r, const glm::vec4& col) {
  r = std::max(r, 14.0);
  const double a = r * 0.4;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      double x = c.x + sx * r, y = c.y + sy * r;
      line(h, x, y, x - sx * a, y, col);
      line(h, x, y, x, y - sy * a, col);
    }
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

void hud_outcome_and_menu(const World& w, const CameraSettings& cs, int width, int height, HudLayer& h) {
  if (w.outcome != Outcome::Undecided && !w.paused) {
    std::string msg = w.outcome == Outcome::Victory  ? "VICTORY"
                      : w.outcome == Outcome::Defeat ? "DEFEAT"
                                                     : "TEAM " + w.winner + " WINS";
    const glm::vec4 c = w.outcome == Outcome::Defeat ? kHudRed : kHudGreen;
    text(h, width * 0.5 - msg.size() * 12.0, height * 0.3, 3.0, c, msg);
    if (w.player >= 0) {
      const std::string hint = "Esc: menu (restart, difficulty, quit)";
      text(h, width * 0.5 - hint.size() * 4.8, height * 0.3 + 48, 1.2, kHudWhite, hint);
    }
  }
  if (!w.paused) return;
  quad(h, 0, 0, width, height, {0.0f, 0.0f, 0.05f, 0.55f});
  text(h, width * 0.5 - 60, height * 0.3, 2.5, kHudWhite, "PAUSED");
  for (size_t i = 0; i < cs.pause_items.size(); ++i) {
    const bool sel = int(i) == cs.pause_selection;
    const double y = height * 0.4 + 36.0 * i;
    if (sel) quad(h, width * 0.5 - 130, y - 6, 260, 32, {0.3f, 0.6f, 1.0f, 0.35f});
    text(h, width * 0.5 - 110, y, 1.6, sel ? kHudYellow : kHudWhite, cs.pause_items[i]);
  }
}

void hud_radar(const World& w, const Ship& me, int width, int height, HudLayer& h) {
  const double size = std::min(width, height) * 0.22, cx = width * 0.5, cy = height - size * 0.5 - 12;
  quad(h, cx - size * 0.5, cy - size * 0.5, size, size, kHudBack);
  line(h, cx - size * 0.5, cy, cx + size * 0.5, cy, {0.4f, 0.8f, 0.5f, 0.3f}, 1.0f);
  line(h, cx, cy - size * 0.5, cx, cy + size * 0.5, {0.4f, 0.8f, 0.5f, 0.3f}, 1.0f);
  const glm::dquat inv = glm::conjugate(me.orientation);
  for (const Ship& s : w.ships) {
    if (!s.alive || s.id == me.id) continue;
    glm::dvec3 local = inv * (s.position - me.position);
    double x = local.x / kRadarRange, y = local.z / kRadarRange;
    double len = std::sqrt(x * x + y * y);
    if (len > 1.0) x /= len, y /= len;
    const glm::vec4 c = w.hostile(me, s) ? kHudRed : kHudBlue;
    const double dot = s.id == me.target ? 6.0 : 4.0;
    quad(h, cx + x * size * 0.5 - dot * 0.5, cy + y * size * 0.5 - dot * 0.5, dot, dot, c);
    // Above or below: a short tick shows the height, as in most space-sim radars.
    double up = std::clamp(local.y / kRadarRange, -1.0, 1.0) * size * 0.25;
    line(h, cx + x * size * 0.5, cy + y * size * 0.5, cx + x * size * 0.5, cy + y * size * 0.5 - up, c, 1.0f);
  }
}

void hud_target(const World& w, const Ship& me, const Projector& pr, int width, int height, double alpha,
                HudLayer& h) {
  if (me.target < 0 || !w.ships[me.target].alive) return;
  const Ship& t = w.ships[me.target];
  const glm::dvec3 tp = lerp_pos(t.prev_position, t.position, alpha);
  const glm::vec4 col = w.hostile(me, t) ? kHudRed : kHudBlue;
  glm::dvec2 px;
  double depth = 0;
  const bool in_front = pr.project(tp, px, &depth);
  const bool on_screen = in_front && px.x >= 0 && px.x <= width && px.y >= 0 && px.y <= height;
  if (on_screen) {
    brackets(h, px, t.cls->shield_radius * pr.focal / depth, col);
    // Lead indicator: where to aim the current secondary (or the beam, which is instant).
    const bool plasma = me.secondary == SecondaryWeapon::Plasma && me.cls->plasma.present;
    const double speed = plasma ? me.cls->plasma.speed : me.cls->missile.present ? me.cls->missile.speed : 0.0;
    if (speed > 0) {
      glm::dvec3 rel = t.position - me.position, rv = t.velocity - me.velocity;
      double time = std::sqrt(glm::dot(rel, rel)) / speed;
      for (int i = 0; i < 2; ++i) time = std::sqrt(glm::dot(rel + rv * time, rel + rv * time)) / speed;
      glm::dvec2 lp;
      if (pr.project(tp + rv * time, lp)) {
        const double d = 7;
        line(h, lp.x - d, lp.y, lp.x, lp.y - d, kHudYellow);
        line(h, lp.x, lp.y - d, lp.x + d, lp.y, kHudYellow);
        line(h, lp.x + d, lp.y, lp.x, lp.y + d, kHudYellow);
        line(h, lp.x, lp.y + d, lp.x - d, lp.y, kHudYellow);
      }
    }
  } else {
    // Arrow at the screen edge toward the target.
    glm::dvec3 v = pr.to_view(tp);
    glm::dvec2 dir(v.x, -v.y);
    double len = std::sqrt(dir.x * dir.x + dir.y * dir.y);
    dir = len > 1e-9 ? dir / len : glm::dvec2(0, 1);
    const double r = std::min(width, height) * 0.4;
    glm::dvec2 tip(width * 0.5 + dir.x * r, height * 0.5 + dir.y * r);
    glm::dvec2 side(-dir.y, dir.x);
    glm::dvec2 b0 = tip - dir * 18.0 + side * 10.0, b1 = tip - dir * 18.0 - side * 10.0;
    line(h, tip.x, tip.y, b0.x, b0.y, col, 3.0f);
    line(h, tip.x, tip.y, b1.x, b1.y, col, 3.0f);
    line(h, b0.x, b0.y, b1.x, b1.y, col, 3.0f);
  }
  const double x = width - 230, y = 70;
  const double dist = std::sqrt(glm::dot(t.position - me.position, t.position - me.position));
  text(h, x, y - 40, 1.2, col, t.name + " (" + t.cls->name + ") " + fmt("%.0f m", dist));
  bar(h, x, y, 200, 10, t.cls->shield > 0 ? t.shield / t.cls->shield : 0.0, kHudBlue, "shield");
  bar(h, x, y + 30, 200, 10, t.hull / t.cls->hull, kHudRed, "hull");
}

void hud_own(const World& w, const Ship& me, const Projector& pr, int width, int height, double alpha, HudLayer& h) {
  // Crosshair where the guns converge ahead of the nose.
  const glm::dvec3 pos = lerp_pos(me.prev_position, me.position, alpha);
  const glm::dquat q = glm::slerp(me.prev_orientation, me.orientation, alpha);
  glm::dvec2 c(width * 0.5, height * 0.5);
  pr.project(pos + forward_of(q) * me.cls->beam.range * 0.5, c);
  line(h, c.x - 14, c.y, c.x - 5, c.y, kHudGreen);
  line(h, c.x + 5, c.y, c.x + 14, c.y, kHudGreen);
  line(h, c.x, c.y - 14, c.x, c.y - 5, kHudGreen);
  line(h, c.x, c.y + 5, c.x, c.y + 14, kHudGreen);
  const double x = 24, y = height - 110;
  bar(h, x, y, 220, 12, me.cls->shield > 0 ? me.shield / me.cls->shield : 0.0, kHudBlue, "SHIELD");
  bar(h, x, y + 34, 220, 12, me.hull / me.cls->hull, me.hull < 0.3 * me.cls->hull ? kHudRed : kHudGreen, "HULL");
  bar(h, x, y + 68, 220, 12, me.cls->energy > 0 ? me.energy / me.cls->energy : 0.0, kHudYellow, "ENERGY");
  const char* weapon = me.secondary == SecondaryWeapon::Plasma ? "PLASMA" : "MISSILES";
  text(h, width - 260, height - 60, 1.2, kHudWhite, std::string("beam + ") + weapon);
  text(h, width - 260, height - 36, 1.2, kHudWhite, "kills " + std::to_string(me.kills));
}

void labels(const World& w, const Projector& pr, int width, int height, HudLayer& h) {
  auto put = [&](const glm::dvec3& p, const std::string& label) {
    glm::dvec2 px;
    if (label.empty() || !pr.project(p, px)) return;
    if (px.x < -100 || px.x > width + 100 || px.y < -20 || px.y > height + 20) return;
    text(h, px.x - label.size() * 4.0, px.y, 1.0, kHudWhite, label);
  };
  for (const Prop& p : w.props) put(p.position + glm::dvec3(0, p.radius + 6.0 * p.scale, 0), p.label);
  for (const EffectSpawnDef& e : w.level.effects) put(e.position + glm::dvec3(0, 12.0 * e.scale, 0), e.label);
  // With a fixed camera nobody is "me", so ships get their names (the gallery), below them so
  // they do not collide with labels of effects placed on them.
  if (w.camera_mode != CameraMode::Fixed) return;
  for (const Ship& s : w.ships)
    if (s.alive) put(s.position - glm::dvec3(0, s.cls->shield_radius + 6.0, 0), s.name);
}

}  // namespace

const std::vector<std::string>& required_models(const World& world) { return world.model_paths; }

void build_render_view(const World& w, double alpha, const CameraSettings& cs, int width, int height,
                       RenderView& out) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  width = std::max(width, 1);
  height = std::max(height, 1);
  out.meshes.clear();
  out.particles.clear();
  out.hud = HudLayer{};
  out.starfield_seed = w.seed;

  // Camera: the World's smoothed rig (deterministic), interpolated like everything else.
  const int mode = cs.use_world_mode ? static_cast<int>(w.camera_mode) : cs.mode;
  CameraView& cam = out.camera;
  cam.fov_y_radians = (cs.fov_deg > 0 ? cs.fov_deg : w.level.camera.fov_deg) * kPi / 180.0;
  if (mode == static_cast<int>(CameraMode::Fixed) || w.focus_ship() < 0) {
    cam.position = w.level.camera.position;
    glm::dvec3 d = w.level.camera.look_at - w.level.camera.position;
    double l = std::sqrt(glm::dot(d, d));
    d = l > 1e-9 ? d / l : glm::dvec3(0, 0, -1);
    cam.orientation = glm::quatLookAt(d, std::fabs(d.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0));
  } else {
    cam.position = lerp_pos(w.prev_camera.position, w.camera.position, alpha);
    cam.orientation = glm::normalize(glm::slerp(w.prev_camera.orientation, w.camera.orientation, alpha));
  }
  const int focus = w.focus_ship();
  const bool cockpit = mode == static_cast<int>(CameraMode::Cockpit);

  const double flash_s = 0.5;
  for (const Ship& s : w.ships) {
    if (!s.alive || (cockpit && s.id == focus)) continue;
    MeshInstance m;
    m.model = s.model;
    m.position = lerp_pos(s.prev_position, s.position, alpha);
    m.orientation = glm::normalize(glm::slerp(s.prev_orientation, s.orientation, alpha));
    m.emissive_boost = 1.0f + float(std::max(0.0, axis_value(s.controls.throttle))) * (s.afterburner_on ? 2.0f : 1.0f);
    for (const ExplosionEvent& e : w.explosions) {
      double age = double(w.tick - e.tick) * w.dt;
      double d = std::sqrt(glm::dot(m.position - e.position, m.position - e.position));
      double k = std::max(0.0, 1.0 - age / flash_s) * std::max(0.0, 1.0 - d / (e.radius * 4.0));
      m.flash += glm::vec3(1.0f, 0.6f, 0.25f) * float(2.0 * k);
    }
    out.meshes.push_back(m);
  }
  for (const Prop& p : w.props) {
    MeshInstance m;
    m.model = p.model;
    m.position = p.position;
    m.orientation = p.orientation;
    m.scale = p.scale;
    out.meshes.push_back(m);
  }

  ParticleCamera pc;
  pc.position = cam.position;
  pc.orientation = cam.orientation;
  pc.fov_y_radians = cam.fov_y_radians;
  pc.aspect = double(width) / double(height);
  pc.near_plane = cam.near_plane;
  if (mode != static_cast<int>(CameraMode::Fixed) && w.focus_ship() >= 0)
    pc.velocity = (w.camera.position - w.prev_camera.position) / w.dt;
  w.particles->collect(pc, out.particles);

  HudLayer& h = out.hud;
  if (cs.show_fps) text(h, width - 120, 12, 1.0, kHudWhite, fmt("%.0f fps", cs.fps));
  if (cs.show_hud) {
    const Projector pr{cam.position, glm::conjugate(cam.orientation),
                       (height * 0.5) / std::tan(cam.fov_y_radians * 0.5), width * 0.5, height * 0.5, cam.near_plane};
    text(h, 24, 16, 1.2, kHudWhite, w.level.objective);
    labels(w, pr, width, height, h);
    if (focus >= 0 && w.ships[focus].alive && w.camera_mode != CameraMode::Fixed) {
      const Ship& me = w.ships[focus];
      hud_own(w, me, pr, width, height, alpha, h);
      hud_target(w, me, pr, width, height, alpha, h);
      hud_radar(w, me, width, height, h);
    }
  }
  hud_outcome_and_menu(w, cs, width, height, h);
}

}  // namespace arc
