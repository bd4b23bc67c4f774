#include "game/app/all_settings.h"

#include "audio/audio_settings.h"
#include "game/net/net_settings.h"
#include "game/sim/sim_settings.h"
#include "gfx/render_settings.h"
#include "particles/particle_settings.h"

namespace arc {

Settings all_settings() {
  Settings s;
  register_render_settings(s);
  register_particle_settings(s);
  register_sim_settings(s);
  register_net_settings(s);
  register_audio_settings(s);
  return s;
}

}  // namespace arc
