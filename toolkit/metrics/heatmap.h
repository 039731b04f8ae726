// Error heat maps: a per-pixel error in [0, 1] shown through a fixed colour
// ramp black -> red -> yellow -> white (knots at 0, 1/3, 2/3, 1, linear in
// 8-bit sRGB between them), so that larger errors are brighter.
#pragma once
#include "renderer/image.h"
#include "toolkit/metrics/separable_filter.h"

#include <array>
#include <cstdint>

namespace boxlod {

// The ramp's colour for one error value (clamped to [0, 1]; NaN counts as 1).
std::array<std::uint8_t, 3> heat_color(double error);

// An RGB image of the error plane's size.
Image8 error_heatmap(const Plane& error);

}  // namespace boxlod
