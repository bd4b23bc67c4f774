// particles/sprites.h — the sprite names effects may use, and their layer in the renderer's
// sprite array texture (assets/textures/sprite_<name>.png, loaded in this order).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace arc {

inline constexpr std::array<std::string_view, 6> kSpriteNames = {"blob", "flare", "spark", "smoke", "shield", "glow"};

// Layer index of a sprite name, or nullopt when the name is unknown.
constexpr std::optional<uint16_t> sprite_index(std::string_view name) {
  for (size_t i = 0; i < kSpriteNames.size(); ++i)
    if (kSpriteNames[i] == name) return static_cast<uint16_t>(i);
  return std::nullopt;
}

static_assert(sprite_index("blob") == 0 && sprite_index("glow") == 5, "renderer layer order");

}  // namespace arc
