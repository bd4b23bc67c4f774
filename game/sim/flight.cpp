// game/sim/flight.cpp — the flight model (exact first-order turn response, flight assist or
// Newtonian thrust), a ship's flight through one tick, and the engine exhaust's glow.
#include "game/sim/flight.h"

#include <algorithm>
#include <cmath>

#include "game/sim/geometry.h"
#include "game/sim/world.h"

namespace arc {

void integrate_flight(Ship& s, double h) {
  const ShipClassDef& c = *s.cls;
  const InputFrame& in = s.controls;
  // Angular rates follow the stick exponentially (exact for a first-order response).
  const glm::dvec3 cmd(axis_value(in.pitch) * c.turn_rate[0] * kDeg, -axis_value(in.yaw) * c.turn_rate[1] * kDeg,
                       -axis_value(in.roll) * c.turn_rate[2] * kDeg);
  const double decay = std::exp(-c.turn_response * h);
  s.angular_velocity = cmd + (s.angular_velocity - cmd) * decay;
  const double rate = safe_len(s.angular_velocity);
  if (rate > 0) s.orientation = glm::normalize(s.orientation * glm::angleAxis(rate * h, s.angular_velocity / rate));

  const double boost = s.afterburner_on ? c.afterburner_speed : 1.0;
  const glm::dvec3 fwd = forward_of(s.orientation);
  const glm::dvec3 right = s.orientation * glm::dvec3(1, 0, 0);
  const glm::dvec3 up = s.orientation * glm::dvec3(0, 1, 0);
  // The afterburner is full boost forward from any set throttle; letting go returns to the set one.
  const double throttle = s.afterburner_on ? 1.0 : axis_value(in.throttle);
  const double sx = axis_value(in.strafe_x), sy = axis_value(in.strafe_y);
  const bool assist = !(in.buttons & kFlightAssist);
  if (assist) {
    // Flight assist: thrust toward the commanded velocity, never harder than the engines allow.
    const double fwd_speed = throttle >= 0 ? throttle * c.max_speed * boost : throttle * c.reverse_fraction * c.max_speed;
    const glm::dvec3 want = fwd * fwd_speed + (right * sx + up * sy) * (0.3 * c.max_speed);
    const glm::dvec3 dv = want - s.velocity;
    const double max_dv = c.thrust * boost / c.mass * h;
    const double need = safe_len(dv);
    s.velocity += need <= max_dv ? dv : dv * (max_dv / need);
  } else {
    const glm::dvec3 a = fwd * (throttle * c.thrust * boost / c.mass) + (right * sx + up * sy) * (c.strafe_thrust / c.mass);
    s.velocity += a * h;
  }
  const double limit = c.max_speed * c.afterburner_speed;
  const double speed = safe_len(s.velocity);
  if (speed > limit) s.velocity *= limit / speed;
  s.position += s.velocity * h;
}

void fly_ship(World& w, Ship& s) {
  s.afterburner_on = (s.controls.buttons & kAfterburner) && s.energy > 0;
  if (s.afterburner_on) s.energy = std::max(0.0, s.energy - s.cls->afterburner_energy * w.dt);
  const int substeps = std::max(1, w.options.substeps);
  for (int k = 0; k < substeps; ++k) integrate_flight(s, w.dt / substeps);
}

void update_exhausts(World& w) {
  for (Ship& s : w.ships) {
    if (!s.alive || s.exhaust_fx.empty()) continue;
    double t = std::max(0.0, axis_value(s.controls.throttle));
    // Idle engines keep a faint glow; the afterburner is the only way to full brightness.
    double q = std::round((s.afterburner_on ? 1.0 : 0.15 + 0.55 * t) * 16.0) / 16.0;
    if (q == s.shown_exhaust_intensity) continue;
    for (const EffectHandle& e : s.exhaust_fx)
      for (ClusterHandle ch : e.clusters) w.particles->set_intensity(ch, q);
    s.shown_exhaust_intensity = q;
  }
}

}  // namespace arc
