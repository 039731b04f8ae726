// The greedy order of the hybrid level mode (docs/design.md: The hybrid level
// mode), within a byte budget: from the root's cheapest proxy, repeatedly the
// change (swap a node's proxy, or open the node) with the largest drop of
// error per added byte; a change that would exceed the budget gives way to
// the node's best change that fits. Bytes count each texture once, as a level
// pays for it (paid_textures.h).
#pragma once
#include "toolkit/lod/hybrid/hybrid_proxy.h"
#include "toolkit/lod/hybrid/paid_textures.h"

#include <vector>

namespace boxlod {

// The source's textures a proxy samples: a simplified sub-tree's (a box and
// a baked proxy sample their level's pages, which their bytes count).
std::vector<int> proxy_textures(const PaidTextures& paid, const Proxy& proxy);

// The steps taken within `budget` bytes (infinity: to the original), and the
// bytes and error before any step and after each; deterministic, ties to the
// lower node index.
void order_within(const Model& model, const std::vector<std::vector<Proxy>>& proxies, double budget,
                  std::vector<HybridStep>& steps, std::vector<double>& bytes, std::vector<double>& error);

}  // namespace boxlod
