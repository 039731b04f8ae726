#include "toolkit/metrics/heatmap.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

std::array<std::uint8_t, 3> heat_color(double error) {
    double t = std::isnan(error) ? 1.0 : std::clamp(error, 0.0, 1.0);
    // Three segments: black->red raises R, red->yellow raises G, yellow->white raises B.
    std::array<std::uint8_t, 3> color{};
    for (int c = 0; c < 3; ++c) {
        double ramp = std::clamp(3 * t - c, 0.0, 1.0);
        color[c] = std::uint8_t(std::lround(255 * ramp));
    }
    return color;
}

Image8 error_heatmap(const Plane& error) {
    Image8 out(error.width, error.height, 3);
    for (int y = 0; y < error.height; ++y)
        for (int x = 0; x < error.width; ++x) {
            std::array<std::uint8_t, 3> c = heat_color(*error.at(x, y));
            std::copy(c.begin(), c.end(), out.at(x, y));
        }
    return out;
}

}  // namespace boxlod
