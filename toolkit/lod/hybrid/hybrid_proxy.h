// What may stand in for a sub-tree in the hybrid level mode (hybrid.h), and a
// step of its plan: the data the plan (hybrid.h) and its greedy order
// (hybrid_order.h) share.
#pragma once
#include "toolkit/model/model.h"

#include <vector>

namespace boxlod {

// box: its textured box; simplified: its simplified geometry in the source's
// materials; baked: a simplified geometry sampling its box's baked faces (baked_proxy.h).
enum class ProxyKind { box, simplified, baked };

// One way to draw a sub-tree instead of its geometry.
struct Proxy {
    ProxyKind kind = ProxyKind::box;
    std::vector<Primitive>
        primitives;  // simplified: the sub-tree simplified (the model's materials); baked: positions only
    bool clustered = false;  // simplified by vertex clustering (large sub-trees), else by edge collapse
    int texel_scale = 1;     // box, baked: its texels as at this many times the sizing distance
    double bytes =
        0;  // box: box_bytes_estimate at its texels; simplified: its mesh bytes; baked: both (baked_proxy.h)
    double error =
        0;  // measured: pixels of the sizing view (hybrid_pixel_error summed, mean over the directions)
};

struct HybridStep {
    int node = 0;
    int proxy = -1;  // the node's proxy from this step on; -1: the node is opened
};

}  // namespace boxlod
