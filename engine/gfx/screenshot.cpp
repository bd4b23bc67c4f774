// gfx/screenshot.cpp — the window's back buffer read into an Image for F12.
#include "gfx/screenshot.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace arc {

Image read_window_pixels(int width, int height) {
  Image img;
  img.width = std::max(0, width);
  img.height = std::max(0, height);
  img.rgba.resize(size_t(img.width) * img.height * 4);
  if (img.rgba.empty()) return img;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  flip_rows(img);
  for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
}

}  // namespace arc
