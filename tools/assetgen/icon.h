// tools/assetgen/icon.h — the game's 256×256 application icon (packaging/arcfire.png).
#pragma once
#include <string>

namespace arc::assetgen {

// Writes the icon PNG to `path`: a fighter at the head of a curved fire trail on a starry disc.
void write_icon(const std::string& path);

}  // namespace arc::assetgen
