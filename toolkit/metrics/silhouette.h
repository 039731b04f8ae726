// Silhouette agreement: intersection over union of two coverage masks.
#pragma once
#include "renderer/image.h"

#include <array>
#include <cstdint>
#include <vector>

namespace boxlod {

// One flag per pixel, row-major, top row first.
struct Coverage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> covered;  // 0 or 1
};

// A mask image (e.g. `boxlod render --coverage`): covered where its first
// channel is above 127.
Coverage coverage_from_mask(const Image8& mask);

// A colour image: covered where any of R, G, B differs from `background`.
Coverage coverage_from_background(const Image8& image, std::array<std::uint8_t, 3> background);

// The number of covered pixels.
std::size_t covered_pixels(const Coverage& coverage);

// |A and B| / |A or B|; 1 when neither covers any pixel. Throws
// std::invalid_argument when the sizes differ.
double silhouette_iou(const Coverage& a, const Coverage& b);

}  // namespace boxlod
