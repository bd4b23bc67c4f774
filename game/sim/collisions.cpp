// game/sim/collisions.cpp — ships push each other and bounce off props; hard contacts do damage.
#include "game/sim/collisions.h"

#include <cmath>

#include "game/sim/damage.h"
#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {

void collide_ships(World& w) {
  const size_t n = w.ships.size();
  for (size_t i = 0; i < n; ++i) {
    Ship& a = w.ships[i];
    if (!a.alive) continue;
    for (size_t j = i + 1; j < n; ++j) {
      Ship& b = w.ships[j];
      if (!b.alive) continue;
      glm::dvec3 d = b.position - a.position;
      double r = a.cls->collision_radius + b.cls->collision_radius;
      double dd = glm::dot(d, d);
      if (dd >= r * r) continue;
      double dist = std::sqrt(dd);
      glm::dvec3 nrm = safe_norm(d, glm::dvec3(0, 1, 0));
      double ma = a.cls->mass, mb = b.cls->mass;
      double push = (r - dist);
      a.position -= nrm * (push * mb / (ma + mb));
      b.position += nrm * (push * ma / (ma + mb));
      double vn = glm::dot(b.velocity - a.velocity, nrm);
      if (vn >= 0) continue;
      double jimp = -1.5 * vn / (1.0 / ma + 1.0 / mb);  // restitution 0.5
      a.velocity -= nrm * (jimp / ma);
      b.velocity += nrm * (jimp / mb);
      double damage = 0.2 * -vn;
      glm::dvec3 contact = a.position + nrm * a.cls->collision_radius;
      apply_damage(w, a, damage, contact, b.id);
      apply_damage(w, b, damage, contact, a.id);
    }
    for (const Prop& p : w.props) {
      if (p.radius <= 0) continue;
      glm::dvec3 d = a.position - p.position;
      double r = a.cls->collision_radius + p.radius;
      double dd = glm::dot(d, d);
      if (dd >= r * r) continue;
      glm::dvec3 nrm = safe_norm(d, glm::dvec3(0, 1, 0));
      a.position = p.position + nrm * r;
      double vn = glm::dot(a.velocity, nrm);
      if (vn < 0) {
        a.velocity -= nrm * (1.5 * vn);
        apply_damage(w, a, 0.2 * -vn, p.position + nrm * p.radius, ShipId{});
      }
    }
  }
}

}  // namespace arc
