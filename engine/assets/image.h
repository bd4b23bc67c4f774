// assets/image.h — RGBA8 images as plain CPU data, read and written through OpenImageIO (no GL),
// which lives in a module of its own loaded on the first image (assets/image_codec.h).
//
// load_image() reads any format OpenImageIO knows into RGBA8; load_sprite() also premultiplies
// colour by alpha (Ilmonen eq. 10: tcola = tcol·talpha). save_image() encodes in memory and writes
// through core/file_writer.h (checked, atomic; WriteError). Other failures throw
// arc::InputError("path: what is wrong").
//
// Example, compiled as AssetExamples.LoadAndSaveAnImage in tests/unit/assets/test_asset_examples.cpp:
//   arc::Image smoke = arc::load_sprite("assets/textures/sprite_smoke.png");
//   arc::save_image(out_dir + "/smoke.png", smoke);
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width*height*4, rows top to bottom
  bool premultiplied = false;
};

Image load_image(const std::string& path);
Image load_sprite(const std::string& path);  // RGBA8, premultiplied
void premultiply(Image& image);
// Reverses the row order (GL reads images bottom to top; Image rows run top to bottom).
void flip_rows(Image& image);
// RGBA8 encoded in memory as the format of path's extension (PNG), through OpenImageIO.
std::vector<uint8_t> encode_image(const std::string& path, const Image& image);
// encode_image(), then written through core/file_writer.h: checked, atomic, WriteError on failure.
void save_image(const std::string& path, const Image& image);

}  // namespace arc
