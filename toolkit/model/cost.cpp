#include "toolkit/model/cost.h"

#include <algorithm>
#include <map>
#include <set>

namespace boxlod {
namespace {

// The sum of `per_level(w, h)` over a full mip chain: level i is
// max(1, w >> i) x max(1, h >> i), down to 1 x 1 (glTF 2.0 / OpenGL mipmapping).
template <typename PerLevel>
std::uint64_t sum_over_mip_chain(int width, int height, PerLevel per_level) {
    std::uint64_t sum = 0;
    for (std::uint64_t w = std::uint64_t(std::max(width, 0)), h = std::uint64_t(std::max(height, 0));
         w > 0 && h > 0;) {
        sum += per_level(w, h);
        if (w == 1 && h == 1) break;
        w = std::max<std::uint64_t>(1, w / 2);
        h = std::max<std::uint64_t>(1, h / 2);
    }
    return sum;
}

// Whether any texel's alpha is below 255 (`partial`: strictly between 0 and 255).
bool has_alpha(const Image8& image, bool partial = false) {
    if (image.channels != 4 && image.channels != 2) return false;
    for (std::size_t i = std::size_t(image.channels - 1); i < image.pixels.size();
         i += std::size_t(image.channels))
        if (image.pixels[i] != 255 && (!partial || image.pixels[i] != 0)) return true;
    return false;
}

GpuFormat gpu_format(const Texture& texture, TextureUse role) {
    switch (role) {
    case TextureUse::normal: return GpuFormat::bc5;  // x and y; z is rebuilt in the shader
    case TextureUse::scalar: return GpuFormat::bc4;
    case TextureUse::color: break;
    }
    // BC1 keeps 1-bit alpha (cut-outs, baked coverage); anything in between needs BC7.
    return has_alpha(texture.image, true) ? GpuFormat::bc7 : GpuFormat::bc1;
}

// At the format boxlod writes for the role: colour RGBA8 where some texel is
// not opaque, else RGB8; normal RGB8; height 16-bit (8-bit if so stored) grey.
std::uint64_t uncompressed_bytes(const Texture& texture, TextureUse role) {
    if (!texture.image16.empty()) return mip_chain_texels(texture.image16.width, texture.image16.height) * 2;
    std::uint64_t texel_bytes = role == TextureUse::scalar   ? 1
                                : role == TextureUse::normal ? 3
                                : has_alpha(texture.image)   ? 4
                                                             : 3;
    return mip_chain_texels(texture.image.width, texture.image.height) * texel_bytes;
}

unsigned map_bit(MaterialMap map) { return 1u << unsigned(map); }

// Draw calls and meshes add up; each texture sampled as one of `maps` is paid
// once however many parts use it, known by its digest.
ModelCost cost_of_maps(const std::vector<const CostParts*>& parts, unsigned maps) {
    ModelCost cost;
    std::set<TextureDigest> paid;
    for (const CostParts* part : parts) {
        cost.draw_calls += part->draw_calls;
        cost.mesh_bytes += part->mesh_bytes;
        for (const TextureCost& texture : part->textures)
            if ((texture.maps & maps) && paid.insert(texture.digest).second) {
                cost.texture_bytes += texture.bytes;
                cost.texture_bytes_gpu += texture.bytes_gpu;
            }
    }
    return cost;
}

}  // namespace

std::uint64_t mip_chain_texels(int width, int height) {
    return sum_over_mip_chain(width, height, [](std::uint64_t w, std::uint64_t h) { return w * h; });
}

std::uint64_t block_compressed_bytes(int width, int height, GpuFormat format) {
    const std::uint64_t block_bytes = format == GpuFormat::bc1 || format == GpuFormat::bc4 ? 8 : 16;
    return sum_over_mip_chain(width, height, [&](std::uint64_t w, std::uint64_t h) {
        return (w + 3) / 4 * ((h + 3) / 4) * block_bytes;
    });
}

std::map<int, TextureCost> texture_costs(const Model& model, const std::set<int>& materials) {
    // Each texture once, in the use of the first material that samples it,
    // with every map any material samples it as.
    struct Sampled {
        TextureUse use;
        unsigned maps = 0;
    };
    std::map<int, Sampled> sampled;
    for (int m : materials) {
        if (m < 0 || m >= int(model.materials.size())) continue;
        const Material& material = model.materials[std::size_t(m)];
        for (auto [index, use, map] : texture_slots(material))
            if (index >= 0 && index < int(model.textures.size()))
                sampled.emplace(index, Sampled{use}).first->second.maps |= map_bit(map);
    }
    std::map<int, TextureCost> costs;
    for (auto [index, texture_sampled] : sampled) {
        const Texture& texture = model.textures[std::size_t(index)];
        const TextureUse use = texture_sampled.use;
        const bool wide = !texture.image16.empty();
        const int width = wide ? texture.image16.width : texture.image.width;
        const int height = wide ? texture.image16.height : texture.image.height;
        costs[index] = {texture_digest(texture), uncompressed_bytes(texture, use),
                        block_compressed_bytes(width, height, gpu_format(texture, use)),
                        texture_sampled.maps};
    }
    return costs;
}

CostParts cost_parts(const Model& model) {
    CostParts parts;
    std::set<int> materials;
    std::set<DrawCallKey> draw_calls;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) {
            materials.insert(p.material);
            if (!p.indices.empty()) draw_calls.insert(draw_call_key(p));
            parts.mesh_bytes += primitive_mesh_bytes(p, model);
        }
    parts.draw_calls = draw_calls.size();
    for (auto& [index, cost] : texture_costs(model, materials)) parts.textures.push_back(cost);
    return parts;
}

ModelCost combined_cost(const std::vector<const CostParts*>& parts) { return cost_of_maps(parts, ~0u); }

ModelCost drawn_cost(const std::vector<const CostParts*>& parts, RenderMode mode) {
    const MapsDrawn drawn = maps_drawn(mode);
    unsigned maps = 0;
    if (drawn.color) maps |= map_bit(MaterialMap::base_color);
    // Specular maps go with lit, mapped shading (boxlod's own shading reads the
    // material's specular colour; an engine's would sample them).
    if (drawn.normal) maps |= map_bit(MaterialMap::normal) | map_bit(MaterialMap::specular);
    if (drawn.height) maps |= map_bit(MaterialMap::height);
    return cost_of_maps(parts, maps);
}

ModelCost model_cost(const Model& model) {
    CostParts parts = cost_parts(model);
    return combined_cost({&parts});
}

KeyValues cost_entries(const ModelCost& cost, const std::string& suffix) {
    return {
        number_entry("draw_calls" + suffix, double(cost.draw_calls)),
        number_entry("mesh_bytes" + suffix, double(cost.mesh_bytes)),
        number_entry("texture_bytes" + suffix, double(cost.texture_bytes)),
        number_entry("texture_bytes_gpu" + suffix, double(cost.texture_bytes_gpu)),
        number_entry("bytes" + suffix, double(cost.bytes())),
    };
}

}  // namespace boxlod
