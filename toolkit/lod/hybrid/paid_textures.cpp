#include "toolkit/lod/hybrid/paid_textures.h"

#include "toolkit/model/cost.h"

#include <algorithm>
#include <iterator>
#include <map>

namespace boxlod {

PaidTextures paid_textures(const Model& model) {
    std::set<int> materials;
    for (std::size_t m = 0; m < model.materials.size(); ++m) materials.insert(int(m));
    std::map<TextureDigest, int> distinct;
    std::map<int, int> of_texture;  // texture index -> distinct texture
    PaidTextures paid;
    for (const auto& [index, cost] : texture_costs(model, materials)) {
        const auto [it, added] = distinct.emplace(cost.digest, int(paid.bytes.size()));
        if (added) paid.bytes.push_back(double(cost.bytes_gpu));
        of_texture[index] = it->second;
    }
    paid.of_material.resize(model.materials.size());
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        std::vector<int>& textures = paid.of_material[m];
        for (auto [index, use, map] : texture_slots(model.materials[m]))
            if (const auto it = of_texture.find(index); it != of_texture.end())
                textures.push_back(it->second);
        std::sort(textures.begin(), textures.end());
        textures.erase(std::unique(textures.begin(), textures.end()), textures.end());
    }
    return paid;
}

std::vector<int> united(const std::vector<int>& a, const std::vector<int>& b) {
    std::vector<int> both;
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
    return both;
}

std::vector<int> textures_of(const PaidTextures& paid, const std::vector<Primitive>& primitives) {
    std::vector<int> textures;
    for (const Primitive& p : primitives)
        if (p.material >= 0 && std::size_t(p.material) < paid.of_material.size())
            textures = united(textures, paid.of_material[std::size_t(p.material)]);
    return textures;
}

double bytes_of(const PaidTextures& paid, const std::vector<int>& textures) {
    double bytes = 0;
    for (int t : textures) bytes += paid.bytes[std::size_t(t)];
    return bytes;
}

std::vector<std::vector<int>> node_textures(const Model& model, const PaidTextures& paid) {
    std::vector<std::vector<int>> textures;
    for (const Node& node : model.nodes) textures.push_back(textures_of(paid, node.primitives));
    return textures;
}

namespace {

// Each node's textures and those of its sub-tree below it, united upwards.
std::vector<std::vector<int>> united_upwards(const Model& model, std::vector<std::vector<int>> textures) {
    for (std::size_t n = model.nodes.size(); n-- > 1;) {  // children after their parents (model.h)
        const auto parent = std::size_t(model.nodes[n].parent);
        textures[parent] = united(textures[parent], textures[n]);
    }
    return textures;
}

}  // namespace

std::vector<std::vector<int>> subtree_textures(const Model& model, const PaidTextures& paid) {
    return united_upwards(model, node_textures(model, paid));
}

std::vector<std::vector<int>> exclusive_textures(const Model& model, const PaidTextures& paid) {
    std::vector<int> depth(model.nodes.size(), 0);
    for (std::size_t n = 1; n < model.nodes.size(); ++n)
        depth[n] = depth[std::size_t(model.nodes[n].parent)] + 1;
    auto common_ancestor = [&](int a, int b) {
        while (a != b) {
            if (depth[std::size_t(a)] < depth[std::size_t(b)]) std::swap(a, b);
            a = model.nodes[std::size_t(a)].parent;
        }
        return a;
    };
    // A texture is the sub-tree's alone where the sub-tree holds every node that samples it.
    std::vector<int> lowest(paid.bytes.size(), -1);  // per texture: the lowest common ancestor of its nodes
    const std::vector<std::vector<int>> own = node_textures(model, paid);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (int t : own[n])
            lowest[std::size_t(t)] =
                lowest[std::size_t(t)] < 0 ? int(n) : common_ancestor(lowest[std::size_t(t)], int(n));
    std::vector<std::vector<int>> textures(model.nodes.size());
    for (std::size_t t = 0; t < lowest.size(); ++t)
        if (lowest[t] >= 0) textures[std::size_t(lowest[t])].push_back(int(t));
    return united_upwards(model, std::move(textures));
}

double DrawnTextures::apply(const std::vector<int>& removed,
                            const std::vector<const std::vector<int>*>& added) {
    double bytes = 0;  // added before removed: a texture both sample stays paid
    for (const std::vector<int>* part : added)
        for (int t : *part)
            if (parts_[std::size_t(t)]++ == 0) bytes += paid_.bytes[std::size_t(t)];
    for (int t : removed)
        if (--parts_[std::size_t(t)] == 0) bytes -= paid_.bytes[std::size_t(t)];
    return bytes;
}

double DrawnTextures::change(const std::vector<int>& removed,
                             const std::vector<const std::vector<int>*>& added) {
    const double bytes = apply(removed, added);
    for (const std::vector<int>* part : added)
        for (int t : *part) --parts_[std::size_t(t)];
    for (int t : removed) ++parts_[std::size_t(t)];
    return bytes;
}

}  // namespace boxlod
