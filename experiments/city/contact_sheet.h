// A contact sheet: frames shrunk to thumbnails on a grid, each labelled, so a
// whole fly-through can be judged at a glance.
#pragma once
#include "renderer/image.h"

#include <string>
#include <vector>

namespace boxlod {

// `image` scaled by 1/factor (an integer >= 1) with a box filter: each output pixel
// is the rounded mean of a factor x factor block (partial blocks at the right and
// bottom edges average what they cover). RGB(A) kept.
Image8 shrink(const Image8& image, int factor);

// Tiles (all of one size) left to right, top to bottom on `columns` columns, with a
// 2-pixel dark gap between them; each tile's label is drawn on a dark strip along its
// top edge. Empty for no tiles.
Image8 contact_sheet(const std::vector<Image8>& tiles, const std::vector<std::string>& labels, int columns);

}  // namespace boxlod
