// game/sim/input.h — one tick of player input, quantised.
//
// Live devices (keyboard, mouse, gamepad) and replay scripts both produce InputFrames, and the
// simulation only ever sees InputFrames. Axes are stored as signed bytes: live input passes
// through exactly the quantisation a recording stores (Doom's demo trick), so a recorded
// session replays bit for bit.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace arc {

enum InputButton : uint16_t {
  kFirePrimary = 1 << 0,    // lightning beam (held)
  kFireSecondary = 1 << 1,  // missiles / the second weapon (held)
  kAfterburner = 1 << 2,
  kFlightAssist = 1 << 3,   // held: assist off (pure Newtonian)
};

// Discrete commands issued on a tick (edge-triggered).
enum class Command : uint8_t {
  None = 0,
  TargetNext,
  TargetNearest,
  TargetNextHostile,
  SwitchWeapon,
  CameraToggle,
  Pause,
  Resume,
  CameraPadlock,  // padlock view on, or back to chase
  Countermeasure,  // drop a decoy flare against incoming missiles
  OrderAttack,     // wing orders: attack the player's target,
  OrderCover,      //   cover the player (engage whoever attacks them),
  OrderFormUp,     //   form up on the player,
  OrderEngage,     //   engage at will
  TargetSubsystem,  // the next turret or subsystem of the target, then the whole ship again
};

struct InputFrame {
  int8_t pitch = 0, yaw = 0, roll = 0;   // −127..127 → −1..1 of max turn rate
  int8_t throttle = 0;                   // −127..127: commanded forward speed fraction (assist) / thrust
  int8_t strafe_x = 0, strafe_y = 0;     // lateral and vertical thrust
  uint16_t buttons = 0;                  // InputButton bits
  bool operator==(const InputFrame&) const = default;
};

// One player slot's tick in a network match: its InputFrame and the commands it issued.
struct SlotInput {
  InputFrame input;
  std::vector<Command> commands;
  bool operator==(const SlotInput&) const = default;
};

inline int8_t quantise_axis(double v) {
  if (!std::isfinite(v)) return 0;
  v = std::clamp(v, -1.0, 1.0);
  return static_cast<int8_t>(std::lround(v * 127.0));
}
inline double axis_value(int8_t q) { return std::max(-1.0, double(q) / 127.0); }

}  // namespace arc
