#include "particles/particle_settings.h"

#include "core/settings.h"

namespace arc {

void register_particle_settings(Settings& s) {
  s.define_integer("particles.budget", 400000, 1000, 4000000,
                   "largest number of live particles; costs memory, and CPU time with the particles alive");
  s.define_integer("particles.lightning_interval", 0, 0, 60,
                   "re-evaluate lightning every n ticks; 0 keeps each effect's own interval;"
                   " a longer one saves CPU time");
  s.define_number("particles.cull_distance", 20000.0, 100.0, 1e12,
                  "clusters farther than this from the camera are not animated until needed;"
                  " a shorter one saves CPU time");
}

}  // namespace arc
