#include "toolkit/model/model_subtree.h"

#include <algorithm>

namespace boxlod {

int MaterialCopier::texture(int index) {
    if (index < 0) return -1;
    auto [it, added] = textures.emplace(index, int(out.textures.size()));
    if (added) out.textures.push_back(source.textures[index]);
    return it->second;
}

int MaterialCopier::material(int index) {
    if (index < 0) return -1;
    auto it = materials.find(index);
    if (it != materials.end()) return it->second;
    Material m = source.materials[index];
    for (const auto& slot : texture_slots(m)) *slot.index = texture(*slot.index);
    out.materials.push_back(m);
    return materials[index] = int(out.materials.size()) - 1;
}

Model extract_subtree(const Model& model, int root) {
    Model out;
    keep_provenance(model, out);
    out.is_lod = model.is_lod;  // a part of an LoD is one too: viewed, never built from again
    MaterialCopier copier{model, out};
    // Depth first, children in order: a parent always comes before its children.
    std::vector<std::pair<int, int>> stack = {{root, -1}};  // (source node, new parent)
    while (!stack.empty()) {
        auto [n, parent] = stack.back();
        stack.pop_back();
        const Node& node = model.nodes[n];
        int index = add_node(out, parent, node.name);
        Node& copy = out.nodes[index];
        copy.rule = node.rule;
        copy.scope = node.scope;
        copy.instance_of = node.instance_of;
        copy.source_id = node.source_id;
        for (const Primitive& primitive : node.primitives) {
            copy.primitives.push_back(primitive);
            copy.primitives.back().material = copier.material(primitive.material);
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, index});
    }
    return out;
}

std::vector<int> subtree_nodes(const Model& model, int root) {
    std::vector<int> nodes;
    for (std::vector<int> pending{root}; !pending.empty();) {
        const int n = pending.back();
        pending.pop_back();
        nodes.push_back(n);
        const std::vector<int>& children = model.nodes[std::size_t(n)].children;
        pending.insert(pending.end(), children.begin(), children.end());
    }
    std::sort(nodes.begin(), nodes.end());
    return nodes;
}

namespace {

// A triangle of non-zero area (an object scaled to nothing draws nothing, and is no object).
bool draws_below(const Model& model, int node) {
    for (std::vector<int> pending{node}; !pending.empty();) {
        const Node& n = model.nodes[std::size_t(pending.back())];
        if (std::any_of(n.primitives.begin(), n.primitives.end(), has_area)) return true;
        pending.pop_back();
        pending.insert(pending.end(), n.children.begin(), n.children.end());
    }
    return false;
}

}  // namespace

std::vector<int> object_nodes(const Model& city) {
    std::vector<int> nodes;
    for (int child : city.nodes[0].children)
        if (draws_below(city, child)) nodes.push_back(child);
    if (std::any_of(city.nodes[0].primitives.begin(), city.nodes[0].primitives.end(), has_area))
        nodes.insert(nodes.begin(), nodes.empty() ? 0 : -1);
    return nodes;
}

Model object_model(const Model& city, int node) {
    if (node >= 0) return extract_subtree(city, node);
    Model model;
    keep_provenance(city, model);
    const Node& root = city.nodes[0];
    const int n = add_node(model, -1, root.name);
    model.nodes[std::size_t(n)].rule = root.rule;
    model.nodes[std::size_t(n)].scope = root.scope;
    MaterialCopier copier{city, model};
    for (Primitive primitive : root.primitives) {
        primitive.material = copier.material(primitive.material);
        model.nodes[std::size_t(n)].primitives.push_back(std::move(primitive));
    }
    return model;
}

}  // namespace boxlod
