#include "toolkit/drawable.h"

#include <map>
#include <tuple>

namespace boxlod {

Drawable make_drawable(const Model& model) {
    Drawable drawable;
    drawable.bounds = model_bounds(model);

    // Colour textures decode sRGB; normal and height maps are linear data.
    std::map<std::pair<int, ColorSpace>, const MipTexture*> decoded;
    auto texture = [&](int index, ColorSpace space) -> const MipTexture* {
        if (index < 0) return nullptr;
        auto key = std::make_pair(index, space);
        if (auto it = decoded.find(key); it != decoded.end()) return it->second;
        drawable.textures.push_back(std::make_unique<MipTexture>(make_texture(model.textures[index].image, space)));
        return decoded[key] = drawable.textures.back().get();
    };

    // Primitives sharing a material and the same attribute set go into one mesh.
    using Key = std::tuple<int, bool, bool, bool>;
    std::map<Key, Mesh*> meshes;
    std::vector<Key> order;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) {
            Key key{p.material, !p.normals.empty(), !p.uvs.empty(), !p.tangents.empty()};
            Mesh*& mesh = meshes[key];
            if (!mesh) {
                drawable.meshes.push_back(std::make_unique<Mesh>());
                mesh = drawable.meshes.back().get();
                order.push_back(key);
            }
            auto base = std::uint32_t(mesh->positions.size());
            mesh->positions.insert(mesh->positions.end(), p.positions.begin(), p.positions.end());
            mesh->normals.insert(mesh->normals.end(), p.normals.begin(), p.normals.end());
            mesh->uvs.insert(mesh->uvs.end(), p.uvs.begin(), p.uvs.end());
            mesh->tangents.insert(mesh->tangents.end(), p.tangents.begin(), p.tangents.end());
            for (std::uint32_t i : p.indices) mesh->indices.push_back(base + i);
        }
    for (const Key& key : order) {
        Batch batch;
        batch.mesh = meshes[key];
        int m = std::get<0>(key);
        if (m >= 0) {
            const Material& material = model.materials[m];
            batch.surface.base_color = material.base_color;
            batch.surface.color = texture(material.base_color_texture, ColorSpace::srgb);
            batch.surface.normal = texture(material.normal_texture, ColorSpace::linear);
            batch.surface.height = texture(material.height_texture, ColorSpace::linear);
            batch.surface.specular = material.specular_color;
            batch.surface.shininess = material.shininess;
        }
        drawable.batches.push_back(batch);
    }
    return drawable;
}

}  // namespace boxlod
