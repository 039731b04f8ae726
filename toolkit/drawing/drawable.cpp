#include "toolkit/drawing/drawable.h"

#include "base/parallel.h"
#include "toolkit/model/vertex_layout.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <mutex>

namespace boxlod {

MipTexture decode_texture(const Texture& texture, ColorSpace space) {
    return texture.image16.empty() ? make_texture(texture.image, space, texture.wrap)
                                   : make_texture(texture.image16, texture.wrap);
}

namespace {

// Equal digests are taken for equal textures: keeping a copy of every image to
// compare instead would double the memory this cache saves.
using Key = std::pair<TextureDigest, ColorSpace>;

}  // namespace

struct TextureCache::Entries {
    mutable std::mutex mutex;
    std::map<Key, std::shared_ptr<const MipTexture>> by_digest;

    std::shared_ptr<const MipTexture> find(const Key& digest) const {
        std::lock_guard lock(mutex);
        auto found = by_digest.find(digest);
        return found == by_digest.end() ? nullptr : found->second;
    }
};

TextureCache::TextureCache() : entries_(std::make_unique<Entries>()) {}
TextureCache::~TextureCache() = default;

std::size_t TextureCache::size() const {
    std::lock_guard lock(entries_->mutex);
    return entries_->by_digest.size();
}

std::shared_ptr<const MipTexture> TextureCache::find(const Texture& texture, ColorSpace space) const {
    return entries_->find({texture_digest(texture), space});
}

std::shared_ptr<const MipTexture> TextureCache::decode(const Texture& texture, ColorSpace space) {
    const Key digest{texture_digest(texture), space};
    if (auto found = entries_->find(digest)) return found;
    // Decoded outside the lock; a thread that lost the race takes the winner's (equal) texture.
    auto decoded = std::make_shared<const MipTexture>(decode_texture(texture, space));
    std::lock_guard lock(entries_->mutex);
    return entries_->by_digest.emplace(digest, decoded).first->second;
}

std::vector<std::pair<int, ColorSpace>> textures_read(const std::vector<Material>& materials) {
    std::vector<std::pair<int, ColorSpace>> read;
    auto add = [&](int index, ColorSpace space) {
        if (index >= 0 && std::find(read.begin(), read.end(), std::pair{index, space}) == read.end())
            read.emplace_back(index, space);
    };
    for (const Material& material : materials) {
        add(material.base_color_texture, ColorSpace::srgb);
        add(material.normal_texture, ColorSpace::linear);
        add(material.height_texture, ColorSpace::linear);
    }
    return read;
}

DecodedTextures decode_textures(const Model& model, TextureCache* cache, int threads) {
    DecodedTextures decoded;
    decoded.color.resize(model.textures.size());
    decoded.linear.resize(model.textures.size());
    const std::vector<std::pair<int, ColorSpace>> wanted =
        textures_read(model.materials);  // decoded in parallel
    parallel_for(wanted.size(), threads, [&](std::size_t i) {
        auto [index, space] = wanted[i];
        const Texture& texture = model.textures[std::size_t(index)];
        (space == ColorSpace::srgb ? decoded.color : decoded.linear)[std::size_t(index)] =
            cache ? cache->decode(texture, space)
                  : std::make_shared<const MipTexture>(decode_texture(texture, space));
    });
    return decoded;
}

Drawable make_drawable(const std::vector<Material>& materials, const DecodedTextures& textures,
                       std::span<const Primitive* const> primitives) {
    Drawable drawable;
    // Primitives sharing a material and the same attribute set go into one mesh,
    // in the order they first appear.
    std::map<DrawCallKey, Mesh*> meshes;
    std::vector<DrawCallKey> order;
    for (const Primitive* p : primitives) {
        for (const Eigen::Vector3f& v : p->positions) drawable.bounds.add(v);
        const DrawCallKey key = draw_call_key(*p);
        Mesh*& mesh = meshes[key];
        if (!mesh) {
            drawable.meshes.push_back(std::make_unique<Mesh>());
            mesh = drawable.meshes.back().get();
            order.push_back(key);
        }
        auto base = std::uint32_t(mesh->positions.size());
        mesh->positions.insert(mesh->positions.end(), p->positions.begin(), p->positions.end());
        mesh->normals.insert(mesh->normals.end(), p->normals.begin(), p->normals.end());
        mesh->uvs.insert(mesh->uvs.end(), p->uvs.begin(), p->uvs.end());
        mesh->tangents.insert(mesh->tangents.end(), p->tangents.begin(), p->tangents.end());
        for (std::uint32_t i : p->indices) mesh->indices.push_back(base + i);
    }
    for (const DrawCallKey& key : order) {
        Batch batch;
        batch.mesh = meshes[key];
        const int m = key.material;
        if (m >= 0) batch.surface = material_surface(materials[std::size_t(m)], textures);
        drawable.batches.push_back(batch);
        drawable.materials.push_back(m);
    }
    return drawable;
}

Drawable make_drawable(const Model& model, const DecodedTextures& textures, int root) {
    std::vector<const Primitive*> primitives;  // the sub-tree's, depth first
    std::vector<int> stack{root};
    while (!stack.empty()) {
        const Node& node = model.nodes[stack.back()];
        stack.pop_back();
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back(*child);
        for (const Primitive& p : node.primitives) primitives.push_back(&p);
    }
    return make_drawable(model.materials, textures, primitives);
}

Surface material_surface(const Material& material, const DecodedTextures& textures) {
    auto texture = [](const std::vector<std::shared_ptr<const MipTexture>>& decoded, int index) {
        return index < 0 ? nullptr : decoded[std::size_t(index)].get();
    };
    Surface surface;
    surface.base_color = material.base_color;
    surface.color = texture(textures.color, material.base_color_texture);
    surface.normal = texture(textures.linear, material.normal_texture);
    surface.height = texture(textures.linear, material.height_texture);
    surface.height_depth = material.height_depth;
    surface.specular = material.specular_color;
    surface.shininess = material.shininess;
    surface.alpha_mode = material.alpha_mode;
    surface.alpha_cutoff = material.alpha_cutoff;
    return surface;
}

std::unique_ptr<DrawableModel> make_drawable_model(const Model& model, TextureCache* cache, int threads) {
    auto result = std::make_unique<DrawableModel>();
    result->textures = decode_textures(model, cache, threads);
    result->drawable = make_drawable(model, result->textures);
    return result;
}

}  // namespace boxlod
