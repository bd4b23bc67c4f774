// game/net/scripted_pilot.h — a deterministic pilot for tests and headless matches
// (`--net-pilot scripted`): every slot flies its own pattern, held for 12 ticks, then another.
#pragma once
#include <cstdint>

#include "core/rng.h"
#include "game/sim/input.h"

namespace arc {

inline SlotInput scripted_pilot_input(int slot, int64_t t) {
  const uint64_t r = key_hash(77, uint64_t(slot), uint64_t(t / 12), 0);
  SlotInput in;
  in.input.pitch = int8_t(int(r & 0xff) % 255 - 127);
  in.input.yaw = int8_t(int((r >> 8) & 0xff) % 255 - 127);
  in.input.throttle = int8_t(64 + int((r >> 16) & 0x3f));
  in.input.buttons = uint16_t((r >> 24) & 0x3);
  if (t % 97 == 0) in.commands.push_back(Command::TargetNextHostile);
  return in;
}

}  // namespace arc
