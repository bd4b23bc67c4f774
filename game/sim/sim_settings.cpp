#include "game/sim/sim_settings.h"

#include "core/settings.h"

namespace arc {

void register_sim_settings(Settings& s) {
  s.define_integer("sim.substeps", 1, 1, 16, "physics sub-steps per tick; each costs CPU time");
  s.define_integer("sim.autopilot", 0, 0, 1, "1: the fighter AI flies the player's ship (mission replays)");
  s.define_integer("sim.threads", 0, 0, 256,
                   "threads that animate particle clusters (0: every core); the result is identical for any count");
}

}  // namespace arc
