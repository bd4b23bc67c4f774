// Contact sheets: frames box-filtered down to thumbnails and tiled on one image.
#include "game/app/contact_sheet.h"

#include <algorithm>
#include <stdexcept>

namespace arc {

namespace {
// Box filter: averages every source pixel that falls into the destination pixel.
void downsample_into(const Image& src, Image& dst, int ox, int oy, int tw, int th) {
  for (int y = 0; y < th; ++y) {
    int y0 = y * src.height / th, y1 = std::max(y0 + 1, (y + 1) * src.height / th);
    for (int x = 0; x < tw; ++x) {
      int x0 = x * src.width / tw, x1 = std::max(x0 + 1, (x + 1) * src.width / tw);
      unsigned sum[4] = {0, 0, 0, 0};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += src.rgba[(size_t(sy) * src.width + sx) * 4 + c];
      unsigned n = unsigned((y1 - y0) * (x1 - x0));
      uint8_t* d = &dst.rgba[(size_t(oy + y) * dst.width + ox + x) * 4];
      for (int c = 0; c < 3; ++c) d[c] = uint8_t((sum[c] + n / 2) / n);
      d[3] = 255;
    }
  }
}
}  // namespace

Image make_contact_sheet(const std::vector<Image>& frames, int columns, int thumb_width) {
  if (frames.empty()) return {};
  const int gutter = 4;
  int fw = frames[0].width, fh = frames[0].height;
  int tw = std::min(thumb_width, fw);
  int th = std::max(1, tw * fh / fw);
  int cols = std::max(1, std::min<int>(columns, int(frames.size())));
  int rows = (int(frames.size()) + cols - 1) / cols;
  Image sheet;
  sheet.width = gutter + cols * (tw + gutter);
  sheet.height = gutter + rows * (th + gutter);
  sheet.rgba.assign(size_t(sheet.width) * sheet.height * 4, 0);
  for (size_t i = 0; i < sheet.rgba.size(); i += 4) {
    sheet.rgba[i] = 18; sheet.rgba[i + 1] = 20; sheet.rgba[i + 2] = 26; sheet.rgba[i + 3] = 255;
  }
  for (size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].width != fw || frames[i].height != fh)
      throw std::invalid_argument("contact sheet frames differ in size");
    int c = int(i) % cols, r = int(i) / cols;
    downsample_into(frames[i], sheet, gutter + c * (tw + gutter), gutter + r * (th + gutter), tw, th);
  }
  return sheet;
}

}  // namespace arc
