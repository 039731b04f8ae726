#include "experiments/sweep/proxy_baked.h"

#include "experiments/sweep/within_budget.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/statistics.h"

#include <optional>

namespace boxlod {

LodParameters proxy_baked_parameters(const LodParameters& sweep, float distance) {
    LodParameters p = sweep;
    p.level_mode = LevelMode::top_down;
    p.budgets.clear();
    p.distance = distance;
    p.level_distances.rule = LevelDistances::Rule::same;
    return p;
}

std::vector<ProxyBakedVariant> proxy_baked_variants(int threads) {
    std::vector<ProxyBakedVariant> variants;
    for (const SimplifyVariant& v : simplify_variants(threads)) {
        if (v.options.budget_by_area) continue;  // one mesh: no budget to split
        for (int scale : {1, 4, 16}) {
            ProxyBakedVariant variant{v.name, v.options, scale};
            variant.simplify.geometry_only = true;
            if (scale > 1) variant.name += " at " + std::to_string(scale) + "x texels";
            variants.push_back(variant);
        }
    }
    return variants;
}

Lod proxy_baked_level(Chain& chain, const ProxyBakedVariant& variant, std::size_t triangles, double budget,
                      int level) {
    const Model& model = chain.model;
    std::optional<Lod> drawn;  // the last level built that draws a triangle
    const std::function<Lod(std::size_t)> make = [&](std::size_t target) {
        const std::vector<Primitive> geometry = simplify_subtree(model, 0, target, variant.simplify);
        Lod lod = chain.build_baked_model(geometry, variant.texel_scale, level);
        if (mesh_counts(lod.model).triangles > 0) drawn = lod;
        return lod;
    };
    if (budget < 0) return make(triangles);
    Lod within = finest_within<Lod>(mesh_counts(model).triangles, budget, make, [](const Lod& lod) {
        return double(combined_cost({&lod.cost}).bytes());
    });
    // A budget only nothing fits: the cheapest level that draws, over it as its bytes say (as the sweep's
    // levels do).
    return mesh_counts(within.model).triangles > 0 || !drawn ? within : std::move(*drawn);
}

}  // namespace boxlod
