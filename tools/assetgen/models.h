// tools/assetgen/models.h — the generated models: three fighter hulls, a corvette, an armour wall, an asteroid.
// Convention: forward −Z, up +Y, right +X, metres, origin at the centre of mass.
#pragma once
#include <string>

namespace arc::assetgen {

// Writes every model into dir (e.g. "assets/models") and the ships' plating textures
// (hull_<class>.png, also embedded in their models) into textures_dir; returns the number of
// files written.
int write_models(const std::string& dir, const std::string& textures_dir);

}  // namespace arc::assetgen
