// The greedy order of the hybrid level mode (docs/design.md: The hybrid level
// mode), within a byte budget: from the root's cheapest proxy, repeatedly the
// change (swap a node's proxy, or open the node) with the largest drop of
// error per added byte; a change that would exceed the budget gives way to
// the node's best change that fits. Bytes count each texture once, as a level
// pays for it (paid_textures.h). And the pruned cut within a budget, which
// the order may start from where it would stall.
#pragma once
#include "toolkit/lod/hybrid/hybrid_proxy.h"
#include "toolkit/lod/hybrid/paid_textures.h"

#include <vector>

namespace boxlod {

// The source's textures a proxy samples: a simplified sub-tree's (a box and
// a baked proxy sample their level's pages, which their bytes count).
std::vector<int> proxy_textures(const PaidTextures& paid, const Proxy& proxy);

// What the order prices changes with, made once per plan: each distinct
// texture's bytes; per node the textures its own geometry, its sub-tree and
// each of its proxies sample, and the bytes of its own and its sub-tree's meshes.
struct PlanPrices {
    PaidTextures paid;
    std::vector<std::vector<int>> own_textures, subtree_textures;
    std::vector<std::vector<std::vector<int>>> proxy_textures;  // per node and proxy
    std::vector<double> own_bytes, subtree_bytes;
};
PlanPrices plan_prices(const Model& model, const std::vector<std::vector<Proxy>>& proxies);

// The steps taken within `budget` bytes (infinity: to the original), and the
// bytes and error before any step and after each; deterministic, ties to the
// lower node index. From `start` where given: its steps first (parents before
// their children), then on greedily.
void order_within(const Model& model, const std::vector<std::vector<Proxy>>& proxies,
                  const PlanPrices& prices, double budget, std::vector<HybridStep>& steps,
                  std::vector<double>& bytes, std::vector<double>& error,
                  const std::vector<int>* start = nullptr);

// The cut within `budget` that minimizes error + lambda x bytes for the least
// lambda whose cut fits, each part's bytes priced with the textures it samples
// alone: the optimal pruning of a tree by a Lagrange multiplier (Chou,
// Lookabaugh and Gray 1989, generalized BFOS), a point of the lower convex
// hull of error against bytes that the greedy order can miss where an opening
// gains nothing until its children change. Per node: its proxy, -1 opened.
// Where no cut fits, the cheapest (the root's cheapest proxy).
std::vector<int> pruned_state_within(const Model& model, const std::vector<std::vector<Proxy>>& proxies,
                                     const PlanPrices& prices, double budget);

}  // namespace boxlod
