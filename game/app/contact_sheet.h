// game/app/contact_sheet.h — many frames on one PNG, for a quick look at a whole session.
#pragma once
#include <vector>

#include "assets/image.h"

namespace arc {

// Lays frames out in a grid of `columns`, each box-filtered down to thumb_width (aspect kept),
// with a 4-pixel dark gutter. All frames must have the same size.
Image make_contact_sheet(const std::vector<Image>& frames, int columns, int thumb_width);

}  // namespace arc
