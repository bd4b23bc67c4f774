// gfx/screenshot.h — reads the window's back buffer (after Renderer::render, before the swap)
// into an RGBA8 image, rows top to bottom, for the F12 screenshot key.
#pragma once
#include "assets/image.h"

namespace arc {

Image read_window_pixels(int width, int height);

}  // namespace arc
