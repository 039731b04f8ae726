#include "toolkit/drawable.h"

#include <map>
#include <tuple>

namespace boxlod {

DecodedTextures decode_textures(const Model& model) {
    DecodedTextures decoded;
    decoded.color.resize(model.textures.size());
    decoded.linear.resize(model.textures.size());
    auto decode = [&](int index, ColorSpace space) {
        if (index < 0) return;
        auto& slot = (space == ColorSpace::srgb ? decoded.color : decoded.linear)[index];
        if (slot) return;
        const Texture& texture = model.textures[index];
        slot = std::make_unique<MipTexture>(texture.image16.empty() ? make_texture(texture.image, space)
                                                                    : make_texture(texture.image16, Wrap::repeat));
    };
    for (const Material& material : model.materials) {
        decode(material.base_color_texture, ColorSpace::srgb);
        decode(material.normal_texture, ColorSpace::linear);
        decode(material.height_texture, ColorSpace::linear);
    }
    return decoded;
}

Drawable make_drawable(const Model& model, const DecodedTextures& textures, int root) {
    Drawable drawable;
    // Primitives sharing a material and the same attribute set go into one mesh,
    // in the order the sub-tree first uses them.
    using Key = std::tuple<int, bool, bool, bool>;
    std::map<Key, Mesh*> meshes;
    std::vector<Key> order;
    std::vector<int> stack{root};
    while (!stack.empty()) {
        const Node& node = model.nodes[stack.back()];
        stack.pop_back();
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back(*child);
        for (const Primitive& p : node.primitives) {
            for (const Eigen::Vector3f& v : p.positions) drawable.bounds.add(v);
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
    }
    auto texture = [](const std::vector<std::unique_ptr<MipTexture>>& decoded, int index) {
        return index < 0 ? nullptr : decoded[index].get();
    };
    for (const Key& key : order) {
        Batch batch;
        batch.mesh = meshes[key];
        if (int m = std::get<0>(key); m >= 0) {
            const Material& material = model.materials[m];
            batch.surface.base_color = material.base_color;
            batch.surface.color = texture(textures.color, material.base_color_texture);
            batch.surface.normal = texture(textures.linear, material.normal_texture);
            batch.surface.height = texture(textures.linear, material.height_texture);
            batch.surface.specular = material.specular_color;
            batch.surface.shininess = material.shininess;
            batch.surface.alpha_cutout = material.alpha_cutout;
        }
        drawable.batches.push_back(batch);
    }
    return drawable;
}

std::unique_ptr<DrawableModel> make_drawable_model(const Model& model) {
    auto result = std::make_unique<DrawableModel>();
    result->textures = decode_textures(model);
    result->drawable = make_drawable(model, result->textures);
    return result;
}

}  // namespace boxlod
