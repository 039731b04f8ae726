// Text drawn into an image with stb_easy_font (the built-in bitmap font of
// Debian's stb): the viewer's on-screen settings and statistics.
#pragma once
#include "renderer/image.h"

#include <string>

namespace boxlod {

// Draws `text` (printable ASCII, '\n' starts a new line) with its top-left
// corner at (x, y), each font pixel `scale` x `scale` image pixels, onto an
// RGB or RGBA image. Returns the height drawn in pixels.
int draw_text(Image8& image, int x, int y, const std::string& text, const std::uint8_t color[3],
              int scale = 1);

}  // namespace boxlod
