// tools/assetgen/models.cpp — hulls built from lofted cross-sections. Each hull is designed so
// its silhouette reads from a chase camera (wings and engine glow) and from the side (nose,
// canopy, fins); the exhaust and gun positions match assets/ships/*.json. Team stripes (fins,
// wing tips) and engine nozzles are materials that take the ship's team colour in the game.
#include "models.h"
#include <cmath>
#include <map>
#include <glm/geometric.hpp>
#include "core/rng.h"
#include "hull_textures.h"
#include "mesh_builder.h"

namespace arc::assetgen {
namespace {

enum Slot { kHull = 0, kTrim = 1, kGlow = 2, kTeamStripe = 3, kEngineGlow = 4, kPortLight = 5, kStarboardLight = 6 };

// How each class looks: hull and trim colours (distinct in tone and hue from each other and
// from the default team colours, so class and team read apart), the glow of its canopy and
// engines, and its plating pattern.
struct ClassLook {
  std::string name;
  glm::vec4 hull;
  glm::vec3 glow;
  HullPattern plating;
  double metres_per_tile;
};

// The last two team slots take the team colour: stripes their albedo, nozzles their glow's hue
// (the colours given here are what a ship of a team without a colour shows). Hull, trim and
// stripes carry the plating detail texture; running lights are red to port, green to starboard.
std::vector<MaterialDef> ship_materials(const ClassLook& look) {
  const glm::vec4 trim(glm::vec3(look.hull) * 0.32f, 1.0f);
  return {{"hull", look.hull, {0, 0, 0}, 0.3f, 0.42f, 0.0f, true},
          {"trim", trim, {0, 0, 0}, 0.7f, 0.35f, 0.0f, true},
          {"glow", {0.1f, 0.1f, 0.1f, 1.0f}, look.glow, 0.0f, 1.0f},
          {"team_stripe", {0.8f, 0.8f, 0.82f, 1.0f}, {0, 0, 0}, 0.3f, 0.5f, 1.0f, true},
          {"engine_glow", {0.1f, 0.1f, 0.1f, 1.0f}, look.glow, 0.0f, 1.0f, 1.0f},
          {"port_light", {0.1f, 0.1f, 0.1f, 1.0f}, {1.0f, 0.1f, 0.06f}, 0.0f, 1.0f},
          {"starboard_light", {0.1f, 0.1f, 0.1f, 1.0f}, {0.12f, 1.0f, 0.3f}, 0.0f, 1.0f}};
}

// Plating texture into textures_dir, embedded into the model too; then the model itself.
void write_ship(MeshBuilder& mb, const ClassLook& look, const std::string& models_dir, const std::string& textures_dir) {
  mb.set_detail_texture(write_hull_texture(textures_dir + "/hull_" + look.name + ".png", look.plating),
                        look.metres_per_tile);
  mb.write_glb(models_dir + "/" + look.name + ".glb", look.name, ship_materials(look));
}

// A pair of running lights: small glowing blocks centred at (±x, y, z), red on the left (−X).
void running_lights(MeshBuilder& mb, double x, double y, double z, double size = 0.45) {
  const glm::dvec3 half(size * 0.5);
  mb.add(box(glm::dvec3(x, y, z) - half, glm::dvec3(x, y, z) + half, kStarboardLight));
  mb.add(box(glm::dvec3(-x, y, z) - half, glm::dvec3(-x, y, z) + half, kPortLight));
}

// An engine pod along +Z ending in a recessed, glowing nozzle whose centre is at (x, y, z_end).
Solid engine(double x, double y, double z_front, double z_end, double r, int sides) {
  const double len = z_end - z_front;
  return loft({circle_z(z_front, r * 0.55, sides, x, y), circle_z(z_front + 0.2 * len, r, sides, x, y),
               circle_z(z_end - 0.15 * len, r * 1.02, sides, x, y), circle_z(z_end, r * 0.85, sides, x, y),
               circle_z(z_end, r * 0.62, sides, x, y), circle_z(z_end - 0.35, r * 0.62, sides, x, y)},
              {kTrim, kHull, kTrim, kTrim, kEngineGlow}, kTrim, kEngineGlow);
}

// A canopy bubble on top of a fuselage: glowing glass between z0 and z1.
Solid canopy(double z0, double z1, double y, double w, double h) {
  const double len = z1 - z0;
  return loft({ring_z(z0, 0.05, 0.05, 6, 0, y + 0.05), ring_z(z0 + 0.35 * len, w, h, 6, 0, y),
               ring_z(z0 + 0.8 * len, w * 0.9, h * 0.8, 6, 0, y), ring_z(z1, w * 0.4, h * 0.3, 6, 0, y)},
              {kGlow}, kGlow, kGlow);
}

// A vertical fin: a wing section lofted along +Y instead of +X.
Solid fin(double x, double y_root, double y_tip, double z_root, double root_chord, double z_tip, double tip_chord,
          double thickness, int material = kTrim) {
  auto section = [&](double y, double z, double chord, double t) {
    Ring r = wing_section(0.0, 0.0, z, chord, t);
    for (auto& p : r) p = glm::dvec3(x + (p.y), y, p.z);
    return r;
  };
  return loft({section(y_root, z_root, root_chord, thickness), section(y_tip, z_tip, tip_chord, thickness * 0.5)},
              {material}, material, material);
}

void add_both_sides(MeshBuilder& mb, const Solid& right) {
  mb.add(right);
  mb.add(mirror_x(right));
}

// Viper: nimble fighter, ~14 m. Dart nose, swept wings, twin engines at x = ±1.6, z = 7.
void viper(const std::string& models_dir, const std::string& textures_dir) {
  MeshBuilder mb;
  mb.add(loft({ring_z(-7.6, 0.02, 0.02, 8, 0, -0.1), ring_z(-5.8, 0.45, 0.35, 8, 0, -0.1, 2.6),
               ring_z(-3.5, 0.9, 0.7, 8, 0, 0.0, 2.6), ring_z(-0.5, 1.25, 0.9, 8, 0, 0.05, 3.0),
               ring_z(3.0, 1.3, 0.85, 8, 0, 0.0, 3.0), ring_z(6.0, 0.8, 0.55, 8, 0, 0.0, 3.0)},
              {kHull, kHull, kHull, kHull, kTrim}, kHull, kTrim));
  mb.add(canopy(-4.2, -0.6, 0.75, 0.55, 0.45));
  const Solid wing = loft({wing_section(1.0, -0.1, -1.5, 6.5, 0.35), wing_section(3.5, -0.2, 1.8, 3.6, 0.22),
                           wing_section(6.2, -0.35, 4.0, 1.6, 0.12)},
                          {kHull, kTeamStripe}, kHull, kTrim);
  add_both_sides(mb, wing);
  // Wing-tip cannons point forward along the leading edge.
  add_both_sides(mb, loft({circle_z(2.0, 0.12, 6, 6.2, -0.35), circle_z(5.6, 0.16, 6, 6.2, -0.35)}, {kTrim}, kTrim, kTrim));
  add_both_sides(mb, engine(1.6, 0.0, 1.5, 7.0, 0.62, 8));
  add_both_sides(mb, fin(1.6, 0.5, 2.3, 3.6, 3.0, 5.6, 1.4, 0.25, kTeamStripe));
  add_both_sides(mb, loft({circle_z(-6.9, 0.07, 6, 2.5, -0.4), circle_z(-3.0, 0.12, 6, 2.5, -0.4),
                           circle_z(-1.5, 0.25, 6, 2.5, -0.4)},
                          {kTrim}, kTrim, kTrim));
  running_lights(mb, 6.2, -0.35, 5.72, 0.22);
  const ClassLook look{"viper", {0.8f, 0.81f, 0.83f, 1.0f}, {0.35f, 0.75f, 1.0f}, {.seed = 11, .rows = 8, .plates_per_row = 3}, 6.0};
  write_ship(mb, look, models_dir, textures_dir);
}

// Warden: heavy gunship, ~21 m. Bulky chined hull, side gun pods, three engines at z = 10.
void warden(const std::string& models_dir, const std::string& textures_dir) {
  MeshBuilder mb;
  mb.add(loft({ring_z(-10.2, 1.2, 0.6, 8, 0, -0.5, 3.0), ring_z(-8.8, 2.2, 1.2, 8, 0, -0.3, 3.5),
               ring_z(-4.0, 2.9, 1.9, 8, 0, 0.0, 3.5), ring_z(3.0, 3.2, 2.0, 8, 0, 0.1, 3.5),
               ring_z(7.5, 2.8, 1.6, 8, 0, 0.0, 3.5), ring_z(9.0, 2.2, 1.2, 8, 0, 0.0, 3.0)},
              {kTrim, kHull, kHull, kHull, kTrim}, kTrim, kTrim));
  // Command bridge: a raised block with a glowing window band.
  mb.add(loft({ring_z(-3.5, 0.9, 0.5, 8, 0, 2.1, 4.0), ring_z(-2.8, 1.3, 0.8, 8, 0, 2.3, 4.0),
               ring_z(-1.6, 1.3, 0.8, 8, 0, 2.3, 4.0), ring_z(2.5, 1.5, 0.9, 8, 0, 2.2, 4.0)},
              {kHull, kGlow, kHull}, kHull, kHull));
  // Dorsal spine with a fin at the back.
  mb.add(fin(0.0, 1.6, 4.0, 3.0, 6.0, 6.5, 2.5, 0.5, kTeamStripe));
  // Side pods on stubby pylons; each carries a gun barrel ending at x = ±4 forward.
  const Solid pod = loft({ring_z(-7.5, 0.25, 0.25, 8, 5.2, -0.5), ring_z(-6.0, 1.0, 0.9, 8, 5.2, -0.5, 3.0),
                          ring_z(4.0, 1.1, 1.0, 8, 5.2, -0.5, 3.0), ring_z(7.0, 0.8, 0.7, 8, 5.2, -0.5, 3.0)},
                         {kTeamStripe, kHull, kTrim}, kTeamStripe, kTrim);
  add_both_sides(mb, pod);
  add_both_sides(mb, box({2.8, -0.9, -2.0}, {4.4, -0.1, 3.0}, kTrim));
  add_both_sides(mb, loft({circle_z(-9.6, 0.18, 6, 4.0, -0.5), circle_z(-5.0, 0.24, 6, 4.0, -0.5),
                           circle_z(-3.5, 0.45, 6, 4.0, -0.5)},
                          {kTrim}, kTrim, kTrim));
  add_both_sides(mb, engine(3.0, 0.0, 5.5, 10.0, 0.95, 8));
  mb.add(engine(0.0, 0.0, 5.0, 10.5, 1.15, 8));
  running_lights(mb, 6.33, -0.5, 0.5, 0.45);
  const ClassLook look{"warden", {0.58f, 0.57f, 0.37f, 1.0f}, {1.0f, 0.55f, 0.2f},
                       {.seed = 12, .rows = 6, .plates_per_row = 2, .hatch_share = 0.35}, 9.0};
  write_ship(mb, look, models_dir, textures_dir);
}

// A capital ship's turret: a squat drum on the hull at `base` (its top facing `up`, ±Y or ±X),
// and twin barrels pointing forward (−Z) from it.
void turret(MeshBuilder& mb, glm::dvec3 base, glm::dvec3 up, double r, bool flak) {
  Solid drum = loft({circle_z(-r * 0.9, r, 8, 0, 0), circle_z(r * 0.9, r, 8, 0, 0)}, {kTrim}, kHull, kHull);
  const double barrel = flak ? 0.45 : 0.7, len = flak ? r * 2.2 : r * 3.2;
  Solid guns = loft({circle_z(-len, barrel, 6, -r * 0.4, r * 0.6), circle_z(0.0, barrel * 1.3, 6, -r * 0.4, r * 0.6)},
                    {kTrim}, kGlow, kTrim);
  Solid guns2 = loft({circle_z(-len, barrel, 6, r * 0.4, r * 0.6), circle_z(0.0, barrel * 1.3, 6, r * 0.4, r * 0.6)},
                     {kTrim}, kGlow, kTrim);
  // The drum is built around +Z: turn it so its axis is `up`, then lift it onto the hull.
  auto place = [&](Solid s, bool drum_axis) {
    for (Tri& t : s.tris)
      for (glm::dvec3* p : {&t.a, &t.b, &t.c}) {
        glm::dvec3 q = *p;
        if (drum_axis) q = glm::dvec3(q.x, q.z, -q.y);  // +Z axis to +Y
        if (up.y < -0.5) q = glm::dvec3(q.x, -q.y, q.z);
        if (std::fabs(up.x) > 0.5) q = glm::dvec3(up.x * q.y, -up.x * q.x, q.z);
        *p = base + q;
      }
    return outward(s);
  };
  mb.add(place(drum, true));
  mb.add(place(guns, false));
  mb.add(place(guns2, false));
}

// Corvette: a capital ship, ~200 m from nose (z = −100) to nozzles (z = 100). A long chined
// hull, a bridge tower aft, a shield generator dome amidships, twin engines at x = ±11, z = 100,
// and four turrets where assets/ships/corvette.json mounts them.
void corvette(const std::string& models_dir, const std::string& textures_dir) {
  MeshBuilder mb;
  mb.add(loft({ring_z(-100, 2.0, 1.5, 8, 0, -1.0, 3.0), ring_z(-85, 9.0, 6.0, 8, 0, -0.5, 3.0),
               ring_z(-50, 16.0, 10.0, 8, 0, 0.0, 3.5), ring_z(10, 20.0, 12.0, 8, 0, 0.0, 3.5),
               ring_z(60, 20.0, 12.0, 8, 0, 0.0, 3.5), ring_z(85, 17.0, 10.0, 8, 0, 0.0, 3.0)},
              {kTrim, kHull, kHull, kHull, kTrim}, kTrim, kTrim));
  // Bridge tower with a glowing window band.
  mb.add(loft({ring_z(30, 6.0, 3.0, 8, 0, 13.0, 4.0), ring_z(34, 8.0, 5.0, 8, 0, 16.0, 4.0),
               ring_z(44, 8.0, 5.0, 8, 0, 17.0, 4.0), ring_z(46, 8.0, 5.0, 8, 0, 17.0, 4.0),
               ring_z(58, 7.0, 4.0, 8, 0, 15.0, 4.0)},
              {kHull, kGlow, kHull, kHull}, kHull, kHull));
  // Shield generator: a glowing dome on a collar amidships.
  mb.add(loft({ring_z(-6, 0.5, 0.5, 10, 0, 14.0), ring_z(-4, 5.5, 3.0, 10, 0, 14.0), ring_z(0, 7.0, 5.0, 10, 0, 15.0),
               ring_z(4, 5.5, 3.0, 10, 0, 14.0), ring_z(6, 0.5, 0.5, 10, 0, 14.0)},
              {kGlow, kGlow, kGlow, kGlow}, kGlow, kGlow));
  // Flanking armour belts with the team's stripe, and a keel.
  add_both_sides(mb, box({18.0, -4.0, -40.0}, {22.0, 4.0, 50.0}, kTeamStripe));
  mb.add(box({-3.0, -16.0, -60.0}, {3.0, -10.0, 60.0}, kTrim));
  add_both_sides(mb, fin(6.0, 10.0, 24.0, 62.0, 22.0, 78.0, 10.0, 1.4, kTeamStripe));
  add_both_sides(mb, engine(11.0, 0.0, 70.0, 100.0, 8.0, 10));
  turret(mb, {0, 11.5, -55}, {0, 1, 0}, 4.0, false);
  turret(mb, {0, -11.5, -25}, {0, -1, 0}, 4.0, false);
  turret(mb, {21.5, 0, 15}, {1, 0, 0}, 3.5, true);
  turret(mb, {-21.5, 0, 15}, {-1, 0, 0}, 3.5, true);
  running_lights(mb, 22.5, 0.0, 50.0, 1.2);
  const ClassLook look{"corvette", {0.5f, 0.53f, 0.58f, 1.0f}, {1.0f, 0.6f, 0.3f},
                       {.seed = 14, .rows = 10, .plates_per_row = 4, .hatch_share = 0.3}, 24.0};
  write_ship(mb, look, models_dir, textures_dir);
}

// Dart: interceptor, ~13 m. Long needle, forward-swept fins, one big engine at z = 6.
void dart(const std::string& models_dir, const std::string& textures_dir) {
  MeshBuilder mb;
  mb.add(loft({ring_z(-7.2, 0.01, 0.01, 8), ring_z(-4.5, 0.3, 0.3, 8), ring_z(-1.0, 0.6, 0.6, 8, 0, 0.05, 2.4),
               ring_z(2.5, 0.85, 0.75, 8, 0, 0.05, 2.6), ring_z(4.2, 0.95, 0.8, 8, 0, 0.0, 2.6)},
              {kTrim, kHull, kHull, kHull}, kHull, kTrim));
  mb.add(engine(0.0, 0.0, 3.2, 6.0, 0.9, 8));
  mb.add(canopy(-3.0, -0.2, 0.45, 0.38, 0.35));
  // Forward-swept main fins: the tip's leading edge is ahead of the root's.
  const Solid fin_main = loft({wing_section(0.6, 0.0, 1.0, 3.8, 0.3), wing_section(2.5, 0.05, -0.4, 2.2, 0.18),
                               wing_section(4.2, 0.15, -1.7, 1.1, 0.1)},
                              {kHull, kTeamStripe}, kHull, kGlow);
  add_both_sides(mb, fin_main);
  // Canards near the nose.
  add_both_sides(mb, loft({wing_section(0.35, 0.0, -4.6, 1.3, 0.12), wing_section(1.5, 0.0, -4.2, 0.5, 0.06)},
                          {kTrim}, kTrim, kTrim));
  // Gun barrels under the fins, muzzles at x = ±1.8, z = −5.
  add_both_sides(mb, loft({circle_z(-5.0, 0.08, 6, 1.8, -0.3), circle_z(-1.0, 0.12, 6, 1.8, -0.3),
                           circle_z(0.8, 0.22, 6, 1.8, -0.3)},
                          {kTrim}, kTrim, kTrim));
  // Dorsal and ventral tail fins give the needle a clear side profile.
  mb.add(fin(0.0, 0.6, 2.4, 2.2, 3.0, 4.4, 1.3, 0.2, kTeamStripe));
  mb.add(fin(0.0, -0.6, -1.7, 2.6, 2.4, 4.2, 1.2, 0.2, kTeamStripe));
  running_lights(mb, 4.22, 0.15, -0.6, 0.28);
  const ClassLook look{"dart", {0.42f, 0.43f, 0.5f, 1.0f}, {0.5f, 1.0f, 0.6f}, {.seed = 13, .rows = 10, .plates_per_row = 4}, 5.0};
  write_ship(mb, look, models_dir, textures_dir);
}

// Wall: a 40 × 40 m armour panel in the XY plane facing +Z, 1 m thick, with raised plates,
// grooves between them and a few light strips, so particles have relief to intersect.
void wall(const std::string& dir) {
  MeshBuilder mb;
  mb.add(box({-20, -20, -1.0}, {20, 20, 0.0}, kTrim));
  const int plates = 5;
  const double cell = 40.0 / plates;
  for (int i = 0; i < plates; ++i)
    for (int j = 0; j < plates; ++j) {
      const double x0 = -20.0 + i * cell + 0.35, x1 = x0 + cell - 0.7;
      const double y0 = -20.0 + j * cell + 0.35, y1 = y0 + cell - 0.7;
      const double h = 0.35 + 0.15 * double((i * 3 + j * 5) % 3);
      // A bevelled plate: the top face is inset, so the sides catch light at an angle.
      Ring base = {{x0, y0, 0.0}, {x1, y0, 0.0}, {x1, y1, 0.0}, {x0, y1, 0.0}};
      Ring top = {{x0 + 0.5, y0 + 0.5, h}, {x1 - 0.5, y0 + 0.5, h}, {x1 - 0.5, y1 - 0.5, h}, {x0 + 0.5, y1 - 0.5, h}};
      mb.add(loft({base, top}, {kHull}, kHull, kHull));
      if ((i + 2 * j) % 4 == 1) mb.add(box({x0 + 1.5, y1 - 1.6, h}, {x1 - 1.5, y1 - 1.2, h + 0.08}, kGlow));
    }
  std::vector<MaterialDef> mats = {{"plate", {0.45f, 0.47f, 0.5f, 1.0f}, {0, 0, 0}, 0.7f, 0.5f},
                                   {"frame", {0.2f, 0.21f, 0.23f, 1.0f}, {0, 0, 0}, 0.7f, 0.6f},
                                   {"lights", {0.1f, 0.1f, 0.1f, 1.0f}, {1.0f, 0.8f, 0.4f}, 0.0f, 1.0f}};
  mb.write_glb(dir + "/wall.glb", "wall", mats);
}

// Asteroid: an icosphere subdivided twice (320 faces), pushed in and out by a sum of random
// bumps and craters, ~12 m across.
void asteroid(const std::string& dir) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : v) p = glm::normalize(p);
  std::vector<glm::ivec3> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      v.push_back(glm::normalize(v[size_t(a)] + v[size_t(b)]));
      return midpoint[key] = int(v.size() - 1);
    };
    std::vector<glm::ivec3> next;
    for (const auto& tri : f) {
      const int ab = mid(tri.x, tri.y), bc = mid(tri.y, tri.z), ca = mid(tri.z, tri.x);
      next.insert(next.end(), {{tri.x, ab, ca}, {tri.y, bc, ab}, {tri.z, ca, bc}, {ab, bc, ca}});
    }
    f = std::move(next);
  }
  const Rng rng{0xA57E401Du, 1, 0};
  std::vector<glm::dvec3> bump_dir;
  std::vector<double> bump_size, bump_height;
  for (uint64_t k = 0; k < 22; ++k) {
    bump_dir.push_back(rng.unit_vector(k));
    bump_size.push_back(rng.range(100 + k, 0.2, 0.6));
    bump_height.push_back(rng.range(200 + k, -0.3, 0.3));
  }
  for (auto& p : v) {
    double r = 1.0;
    for (size_t k = 0; k < bump_dir.size(); ++k) {
      const double d = glm::length(p - bump_dir[k]) / bump_size[k];
      r += bump_height[k] * std::exp(-d * d);
    }
    // Elongated like most small bodies.
    p = glm::dvec3(p.x * 1.3, p.y * 0.85, p.z) * (6.0 * r);
  }
  MeshBuilder mb;
  Solid rock;
  for (const auto& tri : f) rock.tris.push_back({0, v[size_t(tri.x)], v[size_t(tri.y)], v[size_t(tri.z)]});
  mb.add(outward(rock));
  mb.write_glb(dir + "/asteroid.glb", "asteroid", {{"rock", {0.42f, 0.38f, 0.34f, 1.0f}, {0, 0, 0}, 0.0f, 0.95f}});
}

}  // namespace

int write_models(const std::string& dir, const std::string& textures_dir) {
  viper(dir, textures_dir);
  warden(dir, textures_dir);
  dart(dir, textures_dir);
  corvette(dir, textures_dir);
  wall(dir);
  asteroid(dir);
  return 10;
}

}  // namespace arc::assetgen
