#include "toolkit/model/vertex_layout.h"

#include <algorithm>

namespace boxlod {

bool maps_normals(const Model& model, int material) {
    if (material < 0 || material >= int(model.materials.size())) return false;
    const Material& m = model.materials[std::size_t(material)];
    return m.normal_texture >= 0 || m.height_texture >= 0;
}

VertexLayout vertex_layout(const Primitive& primitive, const Model& model) {
    const Material* material = primitive.material >= 0 && primitive.material < int(model.materials.size())
                                   ? &model.materials[std::size_t(primitive.material)]
                                   : nullptr;
    const bool mapped = maps_normals(model, primitive.material);
    VertexLayout layout;
    layout.normals = !primitive.normals.empty();
    layout.uvs = !primitive.uvs.empty() && material && samples_textures(*material);
    layout.tangents = !primitive.tangents.empty() && mapped;
    layout.index_bytes = primitive.positions.size() <= 65535 ? 2 : 4;
    return layout;
}

DrawCallKey draw_call_key(const Primitive& primitive) {
    return {primitive.material, !primitive.normals.empty(), !primitive.uvs.empty(),
            !primitive.tangents.empty()};
}

std::uint64_t primitive_mesh_bytes(const Primitive& primitive, const Model& model) {
    const VertexLayout layout = vertex_layout(primitive, model);
    return layout.vertex_bytes() * primitive.positions.size() +
           std::uint64_t(layout.index_bytes) * primitive.indices.size();
}

std::uint64_t mesh_bytes(const std::vector<Primitive>& primitives, const Model& model) {
    std::uint64_t bytes = 0;
    for (const Primitive& p : primitives) bytes += primitive_mesh_bytes(p, model);
    return bytes;
}

}  // namespace boxlod
