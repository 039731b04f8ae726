#include "toolkit/lod/hybrid/draw_calls.h"

#include "toolkit/model/material_merge.h"
#include "toolkit/model/vertex_layout.h"

#include <meshoptimizer.h>

#include <map>
#include <numeric>

namespace boxlod {
namespace {

void append(Primitive& to, const Primitive& from) {
    auto base = std::uint32_t(to.positions.size());
    to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
    to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
    to.uvs.insert(to.uvs.end(), from.uvs.begin(), from.uvs.end());
    to.tangents.insert(to.tangents.end(), from.tangents.begin(), from.tangents.end());
    for (std::uint32_t i : from.indices) to.indices.push_back(base + i);
    to.polygon_count += from.polygon_count;
}

template <typename T>
void remap_attribute(std::vector<T>& values, const std::vector<unsigned>& remap, std::size_t unique) {
    if (values.empty()) return;
    std::vector<T> out(unique);
    meshopt_remapVertexBuffer(out.data(), values.data(), values.size(), sizeof(T), remap.data());
    values = std::move(out);
}

}  // namespace

std::vector<Primitive> merge_primitives(const Model& model, const std::vector<int>& nodes) {
    std::map<DrawCallKey, std::size_t> index;
    std::vector<Primitive> merged;
    for (int n : nodes)
        for (const Primitive& primitive : model.nodes[std::size_t(n)].primitives) {
            if (primitive.indices.empty()) continue;
            const DrawCallKey key = draw_call_key(primitive);
            auto [it, added] = index.try_emplace(key, merged.size());
            if (added) merged.emplace_back().material = key.material;
            append(merged[it->second], primitive);
        }
    return merged;
}

void remap_vertices(Primitive& primitive, const std::vector<unsigned>& remap, std::size_t unique) {
    meshopt_remapIndexBuffer(primitive.indices.data(), primitive.indices.data(), primitive.indices.size(),
                             remap.data());
    remap_attribute(primitive.positions, remap, unique);
    remap_attribute(primitive.normals, remap, unique);
    remap_attribute(primitive.uvs, remap, unique);
    remap_attribute(primitive.tangents, remap, unique);
}

void weld(Primitive& primitive) {
    std::vector<meshopt_Stream> streams = {
        {primitive.positions.data(), sizeof(Eigen::Vector3f), sizeof(Eigen::Vector3f)}};
    if (!primitive.normals.empty())
        streams.push_back({primitive.normals.data(), sizeof(Eigen::Vector3f), sizeof(Eigen::Vector3f)});
    if (!primitive.uvs.empty())
        streams.push_back({primitive.uvs.data(), sizeof(Eigen::Vector2f), sizeof(Eigen::Vector2f)});
    if (!primitive.tangents.empty())
        streams.push_back({primitive.tangents.data(), sizeof(Eigen::Vector4f), sizeof(Eigen::Vector4f)});
    std::vector<unsigned> remap(primitive.positions.size());
    std::size_t unique =
        meshopt_generateVertexRemapMulti(remap.data(), primitive.indices.data(), primitive.indices.size(),
                                         primitive.positions.size(), streams.data(), streams.size());
    remap_vertices(primitive, remap, unique);
}

Model model_of_primitives(const Model& source, std::vector<Primitive> primitives,
                          const std::string& root_name) {
    Model result;
    keep_provenance(source, result);
    result.materials = source.materials;
    result.textures = source.textures;
    result.is_lod = source.is_lod;
    result.lod_params = source.lod_params;
    add_node(result, -1, root_name);
    std::map<int, int> node_of_material;
    for (Primitive& primitive : primitives) {
        const int material = primitive.material;
        auto [it, added] = node_of_material.try_emplace(material, 0);
        if (added)
            it->second = add_node(
                result, 0, material >= 0 ? source.materials[std::size_t(material)].name : "default material");
        result.nodes[std::size_t(it->second)].primitives.push_back(std::move(primitive));
    }
    return result;
}

Model merge_draw_calls(Model model, const std::string& root_name) {
    merge_materials(model);
    std::vector<int> nodes(model.nodes.size());
    std::iota(nodes.begin(), nodes.end(), 0);
    std::vector<Primitive> merged = merge_primitives(model, nodes);
    for (Primitive& primitive : merged) weld(primitive);
    return model_of_primitives(model, std::move(merged), root_name);
}

}  // namespace boxlod
