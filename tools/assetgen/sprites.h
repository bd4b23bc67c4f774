// tools/assetgen/sprites.h — 128×128 straight-alpha RGBA particle sprites.
#pragma once
#include <string>

namespace arc::assetgen {

// Writes sprite_*.png into dir; returns the number of files written.
int write_sprites(const std::string& dir);

}  // namespace arc::assetgen
