// A render as the metrics need it: the image on a white background and the
// pixels it covers (docs/sweeps.md; a chain's error by distance), and an
// original's half of FLIP when it is compared with many.
#pragma once
#include "renderer/renderer.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/silhouette.h"

#include <optional>
#include <vector>

namespace boxlod {

struct Shot {
    Image8 image;
    Coverage coverage;
    std::optional<FlipReference>
        flip_reference;  // an original's, when FLIP is measured: prepared once per view
};

// With `supersampling` k > 1 the render is k times as large on each side and averaged over k x k
// pixels (renderer.h: downsample): edges and detail below a pixel blend as an anti-aliased
// client shows them, and a pixel is covered where any of its samples is.
Shot render_shot(const std::vector<Batch>& batches, const RenderSettings& settings, int width, int height,
                 int supersampling = 1);
constexpr int max_supersampling =
    4;  // the most the sweeps and a chain's switches ask for: 16 samples a pixel

}  // namespace boxlod
