// gfx/ui_texture.h — an RGBA8 image as a GL texture for tool panels (ImGui image widgets).
//
// The workbench's sprite picker shows each sprite as a thumbnail; ImGui draws a texture by its
// GL name (ImTextureID), so gfx makes the texture and the panel only passes the name on.
// Needs the GL context current for its whole life.
#pragma once
#include <cstdint>

#include "assets/image.h"

namespace arc {

class UiTexture {
 public:
  explicit UiTexture(const Image& rgba8);  // rows top to bottom, as load_image() gives them
  ~UiTexture();
  UiTexture(const UiTexture&) = delete;
  UiTexture& operator=(const UiTexture&) = delete;
  uint32_t gl_name() const { return name_; }

 private:
  uint32_t name_ = 0;
};

}  // namespace arc
