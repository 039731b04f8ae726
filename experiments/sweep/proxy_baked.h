// The proxy-baked baseline (docs/sweeps.md): the whole model's geometry
// simplified as one mesh by one of meshoptimizer's variants and drawn with
// the colours and normals of its root box's faces, baked by boxlod's baker
// (baked_proxy.h) with texels 1, 4 or 16 times as large as the sizing's: the
// far level that Simplygon and Unreal's HLOD ship, as a user would make it
// with Debian's meshoptimizer instead of boxlod's levels.
#pragma once
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/hybrid/simplification.h"

#include <cstddef>
#include <string>
#include <vector>

namespace boxlod {

// The parameters of its chain, which only bakes: the sweep's, every level
// sized for `distance`, top-down level values, no budgets.
LodParameters proxy_baked_parameters(const LodParameters& sweep, float distance);

struct ProxyBakedVariant {
    std::string name;          // results.csv's baseline_variant
    SimplifyOptions simplify;  // geometry_only
    int texel_scale = 1;       // its box's texels as at this many times the sizing distance
};
// Edge collapse (then clustering), the same with open borders locked, and
// clustering alone, each at texel scales 1, 4 and 16: 9 variants.
std::vector<ProxyBakedVariant> proxy_baked_variants(int threads);

// The model simplified to `triangles` by `variant`, or, with a budget >= 0,
// as finely as keeps the level's bytes (every texture) within it (where only
// a level drawing nothing would, the cheapest that draws); baked for
// the chain's distance. Its parameters and statistics name it level `level`.
Lod proxy_baked_level(Chain& chain, const ProxyBakedVariant& variant, std::size_t triangles, double budget,
                      int level);

}  // namespace boxlod
