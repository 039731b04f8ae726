#pragma once
// How the hybrid measures a proxy (docs/cost.md: The hybrid level mode): a sub-tree's bounding
// sphere rendered orthographically from the 4 raised corners of a cube, supersampled, and compared pixel by
// pixel with the proxy's renders, each pixel weighed by hybrid_pixel_error.

#include "renderer/renderer.h"
#include "toolkit/model/framing.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace boxlod {

// Where a sub-tree is measured: its bounding sphere seen orthographically from
// the measuring corners, `side` pixels of `pixel` metres a side.
struct MeasuringView {
    Framing sphere;
    float pixel = 1;
    int side = 1;
};

// Measured from the 4 raised corners of a cube (bit k of a corner: + along
// axis k; +Y is up): a building is seen from above its ground, never from
// below, and every such direction lies within 55 degrees of one. The
// tetrahedron's corners, two of them below, weighed parts no viewer sees;
// on views neither set measures from (edges and horizontals) the raised
// corners need fewer bytes by distance (docs/cost.md: Baked proxies).
constexpr std::array<int, 4> measuring_corners = {2, 3, 6, 7};
constexpr int measuring_directions = int(measuring_corners.size());

// The measuring renders of `batches`, from every direction, `view.side` pixels a side
// (downsampled) or twice that (not). Over `underlay` (full-size renders of what every candidate
// is drawn among) when given, from its depth: the picture of the underlay's batches and these in
// one render.
std::vector<Frame> render_views(const std::vector<Batch>& batches, const MeasuringView& view, RenderMode mode,
                                const std::vector<Frame>* underlay = nullptr, bool downsampled = true);

// A measuring pixel as hybrid_pixel_error compares it: its coverage and its
// colour in sRGB bytes, converted once per render rather than per comparison.
struct ComparedPixel {
    float coverage = 0;
    std::array<int, 3> srgb{};
};

// Every direction's pixels, as compared.
std::vector<std::vector<ComparedPixel>> compared_views(const std::vector<Frame>& frames);

// The measuring pixels' errors summed over every direction.
double pixel_error_sum(const std::vector<std::vector<ComparedPixel>>& original,
                       const std::vector<std::vector<ComparedPixel>>& proxy);

// The error of one pixel between two renders of the same view, in [0, 2]:
// the coverage that differs, plus, where both cover, the mean absolute sRGB
// difference of the colours, weighed by the coverage they share.
double hybrid_pixel_error(const Eigen::Vector4f& a, const Eigen::Vector4f& b);

}  // namespace boxlod
