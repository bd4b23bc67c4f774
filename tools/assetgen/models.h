// tools/assetgen/models.h — the generated models: three ship hulls, an armour wall, an asteroid.
// Convention: forward −Z, up +Y, right +X, metres, origin at the centre of mass.
#pragma once
#include <string>

namespace arc::assetgen {

// Writes every model into dir (e.g. "assets/models"); returns the number of files written.
int write_models(const std::string& dir);

}  // namespace arc::assetgen
