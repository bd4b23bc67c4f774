// tools/assetgen/hull_textures.h — tiling hull-plating detail textures for the ship models.
//
// A texture is rows of plates of varying width (offset from row to row like brickwork), each
// a little lighter or darker, with dark panel lines between them, fasteners at the corners and
// a few inset hatches. It is greyscale detail around white, authored as sRGB colour data: the
// model multiplies it with the material's colour, so one pattern serves hull, trim and the
// team-coloured stripes alike, and a renderer that samples it as sRGB (GL_SRGB8_ALPHA8) reads
// the same picture.
//
//   std::string png = write_hull_texture("assets/textures/hull_viper.png", HullPattern{.seed = 1});
#pragma once
#include <cstdint>
#include <string>

namespace arc::assetgen {

struct HullPattern {
  uint64_t seed = 1;
  int rows = 8;              // plate rows per tile
  int plates_per_row = 3;    // plates in a row (their widths are jittered)
  double hatch_share = 0.2;  // share of plates with an inset hatch outline
  double tone_spread = 0.14; // plates vary by this much below white
};

// Writes the texture as a 256×256 PNG at `path` and returns the file's bytes (to embed).
std::string write_hull_texture(const std::string& path, const HullPattern& pattern);

}  // namespace arc::assetgen
