// The hybrid level mode (beyond the manual; docs/design.md: The hybrid level
// mode). Each node may stand in for its sub-tree by one of several proxies:
// its textured box, with texels as the sizing distance gives them or 2 to 16
// times as large, or the sub-tree simplified on its own at a few face
// targets (meshoptimizer's edge collapse, and vertex clustering for large
// sub-trees; the sub-tree's own materials and textures). Each
// proxy's error is measured, not guessed: the sub-tree and the proxy are
// rendered among their siblings, from the 4 raised corners of a cube, orthographically with pixels
// of the sizing view's size (texture_sizing.h; coarser for large parts), and the error
// is the number of pixels that differ, summed as hybrid_pixel_error (hybrid_measuring.h) weighs
// them. Starting from the root's cheapest proxy, a plan repeatedly takes the
// change (swap a node's proxy for a better one, or open the node: its own
// geometry and its children at their cheapest proxies) with the largest drop
// of error per added byte; a level takes that order again within its byte
// budget, changes that would exceed it giving way to those that still fit.
// No peer chooses by measured error per byte: boxes win on flat, detailed
// facades, simplification on curved or thin parts.
#pragma once
#include "renderer/renderer.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/lod/cut/cut.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/hybrid/hybrid_order.h"
#include "toolkit/lod/hybrid/hybrid_proxy.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/model.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace boxlod {

struct HybridPlan {
    // Per node, its proxies by ascending bytes drawn alone (with the textures
    // they sample) and descending error (dominated ones dropped). Empty: the
    // sub-tree is drawn as it is wherever it is reached (no geometry, or
    // geometry cheaper than any proxy).
    std::vector<std::vector<Proxy>> proxies;
    PlanPrices prices;              // what the order prices changes with (order_hybrid_plan makes them)
    std::vector<HybridStep> steps;  // from the root at its cheapest proxy to the original
    std::vector<double> bytes,
        error;  // after k steps: bytes (meshes, box estimates, each texture once) and the summed proxy errors
};

// What plan_hybrid measured, kept for the plans of the same model at other
// sizing distances (chain.h: one plan per distance): a node measured
// again in the same measuring view takes its proxies' errors from here, and
// its simplified sub-trees, which no distance changes, are made once. Each
// node's entry is written by the one thread that measures it.
struct HybridMeasurements;
std::shared_ptr<HybridMeasurements> make_hybrid_measurements(const Model& model);

// What the plan's renders share with the LoD they plan.
struct HybridSettings {
    TextureSizing sizing;
    RenderMode mode = RenderMode::normal;
    int threads = 0;    // nodes measured in parallel; the plan never depends on it
    int max_side = 48;  // measuring renders at most this many pixels a side (coarser pixels weigh more)
    HybridMeasurements* measurements = nullptr;  // set: reused and filled (the same plan as without)
    bool baked_proxies = false;  // also each sub-tree's baked proxies (textured modes; baked_proxy.h)
};

// Measures every proxy and plans. `boxes` as node_boxes gives them; `textures`
// the model's, decoded (unused when the mode is untextured).
HybridPlan plan_hybrid(const Model& model, const DecodedTextures& textures,
                       const std::vector<std::optional<OrientedBox>>& boxes, const HybridSettings& settings);

// The plan's prices, steps, bytes and errors from its proxies (plan_hybrid's
// second half): deterministic, ties to the lower node index.
void order_hybrid_plan(const Model& model, HybridPlan& plan);

// Per node, after `steps` steps of the plan: the proxy it is drawn by (an index
// into plan.proxies[n]) or -1 where it keeps its own geometry. A node matters
// only where every ancestor keeps its geometry.
std::vector<int> hybrid_state(const HybridPlan& plan, std::size_t steps);

// A level of the plan: its state (as hybrid_state's), estimated bytes and error.
struct HybridLevel {
    std::vector<int> state;
    double bytes = 0, error = 0;
};

// The best level within `budget` bytes: the plan's order taken again, a change
// that would exceed the budget giving way to the node's best change that fits,
// once from the root's cheapest proxy and once from the pruned cut within the
// budget (hybrid_order.h); of the states passed within the budget, the
// lowest error (the first of equal error, the greedy order's first). Beyond
// the budget only when nothing within it is reached.
HybridLevel hybrid_level_within(const Model& model, const HybridPlan& plan, double budget);

// The cut of a state (cut.h): nodes at a box proxy in box_nodes (with its
// texel scale), at a simplified one in simplified_nodes; the others keep their geometry.
Cut hybrid_cut(const Model& model, const HybridPlan& plan, const std::vector<int>& state);

// The measured error of a cut of the plan: its proxies' errors summed (its
// box nodes' box proxies, its simplified nodes' proxies), pixels of the sizing view.
double hybrid_cut_error(const HybridPlan& plan, const Cut& cut);

// Levels 1..N at byte budgets B_1..B_N (level_budgets.h; by default geometric
// from the root's cheapest proxy to the original, as error-greedy's): levels[c]
// is level c's (levels[0]: the original); L(n) is the largest level at which n
// keeps its geometry.
LevelValues hybrid_levels(const Model& model, const HybridPlan& plan, const std::vector<double>& budgets,
                          std::vector<HybridLevel>& levels);

}  // namespace boxlod
