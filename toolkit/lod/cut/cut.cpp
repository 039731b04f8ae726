#include "toolkit/lod/cut/cut.h"

namespace boxlod {

int texel_scale(const Cut& cut, int n) {
    const auto scale = cut.box_texel_scales.find(n);
    return scale == cut.box_texel_scales.end() ? 1 : scale->second;
}

Cut take_cut(const Model& model, const std::vector<int>& level, int current_level,
             const std::vector<std::optional<OrientedBox>>& boxes, const std::vector<bool>& kept) {
    Cut cut;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        int n = stack.back();
        stack.pop_back();
        const Node& node = model.nodes[n];
        cut.used_nodes.push_back(n);
        const bool keeps_geometry = !kept.empty() && kept[std::size_t(n)];
        if (level[n] < current_level && !keeps_geometry) {
            if (boxes[n]) cut.box_nodes.push_back(n);  // nothing replaces a sub-tree without geometry
            continue;
        }
        if (node.has_geometry()) cut.geometry_nodes.push_back(n);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back(*child);
    }
    return cut;
}

}  // namespace boxlod
