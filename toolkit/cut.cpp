#include "toolkit/cut.h"

namespace boxlod {

std::vector<std::size_t> subtree_faces(const Model& model) {
    std::vector<std::size_t> faces(model.nodes.size(), 0);
    // A parent comes before its children (model.h), so children are summed first going backwards.
    for (std::size_t n = model.nodes.size(); n-- > 0;) {
        for (const Primitive& primitive : model.nodes[n].primitives) faces[n] += primitive.polygon_count;
        if (model.nodes[n].parent >= 0) faces[std::size_t(model.nodes[n].parent)] += faces[n];
    }
    return faces;
}

Cut take_cut(const Model& model, const std::vector<int>& level, int current_level,
             const std::vector<std::optional<OrientedBox>>& boxes, bool keep_small_subtrees) {
    constexpr std::size_t box_faces = 6;
    std::vector<std::size_t> faces;
    if (keep_small_subtrees) faces = subtree_faces(model);
    Cut cut;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        int n = stack.back();
        stack.pop_back();
        const Node& node = model.nodes[n];
        cut.used_nodes.push_back(n);
        if (level[n] < current_level && !(keep_small_subtrees && faces[std::size_t(n)] <= box_faces)) {
            if (boxes[n]) cut.box_nodes.push_back(n);  // nothing replaces a sub-tree without geometry
            continue;
        }
        if (node.has_geometry()) cut.geometry_nodes.push_back(n);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back(*child);
    }
    return cut;
}

}  // namespace boxlod
