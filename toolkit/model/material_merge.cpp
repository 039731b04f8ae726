#include "toolkit/model/material_merge.h"

#include <algorithm>

namespace boxlod {

std::size_t merge_materials(Model& model) {
    std::vector<bool> drawn(model.materials.size(), false);
    for (const Node& node : model.nodes)
        for (const Primitive& primitive : node.primitives)
            if (primitive.material >= 0) drawn[std::size_t(primitive.material)] = true;
    std::vector<Material> kept;
    std::vector<int> renumbered(model.materials.size(), -1);
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        if (!drawn[m]) continue;
        // Quadratic in the distinct materials: tens even where an importer gives hundreds.
        auto equal = std::find(kept.begin(), kept.end(), model.materials[m]);
        renumbered[m] = int(equal - kept.begin());
        if (equal == kept.end()) kept.push_back(model.materials[m]);
    }
    for (Node& node : model.nodes)
        for (Primitive& primitive : node.primitives)
            if (primitive.material >= 0) primitive.material = renumbered[std::size_t(primitive.material)];
    const std::size_t removed = model.materials.size() - kept.size();
    model.materials = std::move(kept);
    return removed;
}

}  // namespace boxlod
