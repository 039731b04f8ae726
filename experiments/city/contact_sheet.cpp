#include "experiments/city/contact_sheet.h"

#include "renderer/text_overlay.h"

#include <algorithm>
#include <stdexcept>

namespace boxlod {

Image8 shrink(const Image8& image, int factor) {
    if (factor < 1) throw std::invalid_argument("shrink: factor must be at least 1");
    int w = (image.width + factor - 1) / factor, h = (image.height + factor - 1) / factor, c = image.channels;
    Image8 out(w, h, c);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int x1 = std::min(image.width, (x + 1) * factor), y1 = std::min(image.height, (y + 1) * factor);
            int count = (x1 - x * factor) * (y1 - y * factor);
            for (int k = 0; k < c; ++k) {
                int sum = 0;
                for (int sy = y * factor; sy < y1; ++sy)
                    for (int sx = x * factor; sx < x1; ++sx) sum += image.at(sx, sy)[k];
                out.at(x, y)[k] = std::uint8_t((sum + count / 2) / count);
            }
        }
    return out;
}

Image8 contact_sheet(const std::vector<Image8>& tiles, const std::vector<std::string>& labels, int columns) {
    if (tiles.empty()) return {};
    const int gap = 2, strip = 12;
    int w = tiles[0].width, h = tiles[0].height;
    columns = std::clamp(columns, 1, int(tiles.size()));
    int rows = (int(tiles.size()) + columns - 1) / columns;
    Image8 sheet(columns * w + (columns + 1) * gap, rows * h + (rows + 1) * gap, 3, 32);
    const std::uint8_t white[3] = {255, 255, 255};
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const Image8& tile = tiles[i];
        if (tile.width != w || tile.height != h || tile.channels < 3)
            throw std::invalid_argument("contact_sheet: tiles must be RGB(A) images of one size");
        int x0 = gap + int(i) % columns * (w + gap), y0 = gap + int(i) / columns * (h + gap);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::uint8_t* p = tile.at(x, y);
                std::uint8_t* q = sheet.at(x0 + x, y0 + y);
                for (int k = 0; k < 3; ++k)
                    q[k] = y < strip && i < labels.size() ? std::uint8_t(p[k] / 4) : p[k];
            }
        if (i < labels.size()) draw_text(sheet, x0 + 2, y0 + 2, labels[i], white);
    }
    return sheet;
}

}  // namespace boxlod
