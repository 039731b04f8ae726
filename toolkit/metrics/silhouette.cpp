#include "toolkit/metrics/silhouette.h"

#include <algorithm>
#include <stdexcept>

namespace boxlod {

Coverage coverage_from_mask(const Image8& mask) {
    Coverage out{mask.width, mask.height, std::vector<std::uint8_t>(std::size_t(mask.width) * mask.height)};
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x)
            out.covered[std::size_t(y) * mask.width + x] = mask.at(x, y)[0] > 127;
    return out;
}

std::size_t covered_pixels(const Coverage& coverage) {
    return std::size_t(std::count(coverage.covered.begin(), coverage.covered.end(), std::uint8_t(1)));
}

Coverage coverage_from_background(const Image8& image, std::array<std::uint8_t, 3> background) {
    if (image.channels < 3) throw std::invalid_argument("coverage_from_background: RGB image expected");
    Coverage out{image.width, image.height,
                 std::vector<std::uint8_t>(std::size_t(image.width) * image.height)};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            out.covered[std::size_t(y) * image.width + x] =
                p[0] != background[0] || p[1] != background[1] || p[2] != background[2];
        }
    return out;
}

double silhouette_iou(const Coverage& a, const Coverage& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("silhouette_iou: masks differ in size");
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.covered.size(); ++i) {
        both += a.covered[i] & b.covered[i];
        either += a.covered[i] | b.covered[i];
    }
    return either == 0 ? 1.0 : double(both) / double(either);
}

}  // namespace boxlod
