#include "renderer/text_overlay.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace boxlod {

int draw_text(Image8& image, int x, int y, const std::string& text, const std::uint8_t color[3], int scale) {
    // stb_easy_font emits axis-aligned quads: 4 vertices of (x, y, z, rgba) each, 16 bytes.
    std::vector<char> buffer(text.size() * 300 + 1024);
    std::string copy = text;
    int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
        const float* corner = v + q * 16;  // 4 vertices x 4 floats
        float x0 = corner[0], y0 = corner[1], x1 = corner[8], y1 = corner[9];
        int px0 = x + int(std::lround(std::min(x0, x1) * float(scale))),
            px1 = x + int(std::lround(std::max(x0, x1) * float(scale)));
        int py0 = y + int(std::lround(std::min(y0, y1) * float(scale))),
            py1 = y + int(std::lround(std::max(y0, y1) * float(scale)));
        for (int py = std::max(py0, 0); py < std::min(py1, image.height); ++py)
            for (int px = std::max(px0, 0); px < std::min(px1, image.width); ++px)
                std::copy_n(color, 3, image.at(px, py));
    }
    return stb_easy_font_height(copy.data()) * scale;
}

}  // namespace boxlod
