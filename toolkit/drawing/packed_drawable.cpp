#include "toolkit/drawing/packed_drawable.h"

#include <libdeflate.h>

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace boxlod {
namespace {

// Level 1: the fastest; baked pages, flat regions of colour and normals, still deflate well (docs/city.md:
// Scale).
constexpr int compression_level = 1;

// Plain arrays (indices, texels) and Eigen vectors, as their scalars in memory order.
template <typename T>
void append(std::vector<std::uint8_t>& raw, const std::vector<T>& values) {
    if constexpr (std::is_arithmetic_v<T>) {
        const auto* first = reinterpret_cast<const std::uint8_t*>(values.data());
        raw.insert(raw.end(), first, first + values.size() * sizeof(T));
    } else {
        for (const T& v : values) {
            const auto* first = reinterpret_cast<const std::uint8_t*>(v.data());
            raw.insert(raw.end(), first, first + sizeof(float) * T::SizeAtCompileTime);
        }
    }
}

template <typename T>
void take(const std::vector<std::uint8_t>& raw, std::size_t& offset, std::size_t count,
          std::vector<T>& values) {
    values.resize(count);
    if constexpr (std::is_arithmetic_v<T>) {
        std::memcpy(values.data(), raw.data() + offset, count * sizeof(T));
        offset += count * sizeof(T);
    } else {
        for (T& v : values) {
            std::memcpy(v.data(), raw.data() + offset, sizeof(float) * T::SizeAtCompileTime);
            offset += sizeof(float) * T::SizeAtCompileTime;
        }
    }
}

std::size_t mesh_size(const PackedDrawable::MeshSizes& m) {
    return (3 * m.positions + 3 * m.normals + 2 * m.uvs + 4 * m.tangents) * sizeof(float) +
           m.indices * sizeof(std::uint32_t);
}

// Bytes of a texture's mip chain as make_texture keeps it: RGBA8, or 16 bits a texel.
std::size_t mip_chain_size(const PackedDrawable::OwnTexture& t) {
    std::size_t texel = t.channels == 0 ? 2 : 4, total = 0;
    for (int w = t.width, h = t.height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
        total += std::size_t(w) * std::size_t(h) * texel;
        if (w == 1 && h == 1) return total;
    }
}

std::vector<std::uint8_t> deflate(const std::vector<std::uint8_t>& raw) {
    libdeflate_compressor* compressor = libdeflate_alloc_compressor(compression_level);
    if (!compressor) throw std::bad_alloc();
    std::vector<std::uint8_t> out(libdeflate_deflate_compress_bound(compressor, raw.size()));
    std::size_t size =
        libdeflate_deflate_compress(compressor, raw.data(), raw.size(), out.data(), out.size());
    libdeflate_free_compressor(compressor);
    if (size == 0) throw std::runtime_error("pack_drawable: deflate failed");
    out.resize(size);
    out.shrink_to_fit();
    return out;
}

std::vector<std::uint8_t> inflate(const PackedDrawable& packed) {
    std::vector<std::uint8_t> raw(packed.raw_size);
    libdeflate_decompressor* decompressor = libdeflate_alloc_decompressor();
    if (!decompressor) throw std::bad_alloc();
    std::size_t size = 0;
    libdeflate_result result = libdeflate_deflate_decompress(
        decompressor, packed.bytes.data(), packed.bytes.size(), raw.data(), raw.size(), &size);
    libdeflate_free_decompressor(decompressor);
    if (result != LIBDEFLATE_SUCCESS || size != raw.size())
        throw std::runtime_error("unpack_drawable: inflate failed");
    return raw;
}

}  // namespace

PackedDrawable pack_drawable(const Model& model, const TextureCache* shared, bool height_maps) {
    PackedDrawable packed;
    packed.materials = model.materials;
    if (!height_maps)
        for (Material& material : packed.materials) material.height_texture = -1;
    DecodedTextures none;  // the meshes need no decoded textures
    none.color.resize(model.textures.size());
    none.linear.resize(model.textures.size());
    Drawable drawable = make_drawable(model, none);
    packed.bounds = drawable.bounds;
    packed.batch_materials = drawable.materials;

    std::vector<std::uint8_t> raw;
    for (const auto& mesh : drawable.meshes) {
        packed.meshes.push_back({mesh->positions.size(), mesh->normals.size(), mesh->uvs.size(),
                                 mesh->tangents.size(), mesh->indices.size()});
        append(raw, mesh->positions);
        append(raw, mesh->normals);
        append(raw, mesh->uvs);
        append(raw, mesh->tangents);
        append(raw, mesh->indices);
        packed.unpacked_size += mesh_size(packed.meshes.back());
    }
    packed.shared = none;
    for (auto [index, space] : textures_read(packed.materials)) {
        const Texture& texture = model.textures[std::size_t(index)];
        if (auto found = shared ? shared->find(texture, space) : nullptr) {
            (space == ColorSpace::srgb ? packed.shared.color : packed.shared.linear)[std::size_t(index)] =
                found;
            continue;
        }
        PackedDrawable::OwnTexture own{
            index, space, texture.image.width, texture.image.height, texture.image.channels, texture.wrap};
        if (texture.image16.empty()) {
            append(raw, texture.image.pixels);
        } else {
            own.width = texture.image16.width;
            own.height = texture.image16.height;
            own.channels = 0;
            append(raw, texture.image16.pixels);
        }
        packed.unpacked_size += mip_chain_size(own);
        packed.own.push_back(own);
    }
    packed.raw_size = raw.size();
    packed.bytes = deflate(raw);
    return packed;
}

std::unique_ptr<DrawableModel> unpack_drawable(const PackedDrawable& packed) {
    const std::vector<std::uint8_t> raw = inflate(packed);
    auto result = std::make_unique<DrawableModel>();
    Drawable& drawable = result->drawable;
    std::size_t offset = 0;
    for (const PackedDrawable::MeshSizes& sizes : packed.meshes) {
        auto mesh = std::make_unique<Mesh>();
        take(raw, offset, sizes.positions, mesh->positions);
        take(raw, offset, sizes.normals, mesh->normals);
        take(raw, offset, sizes.uvs, mesh->uvs);
        take(raw, offset, sizes.tangents, mesh->tangents);
        take(raw, offset, sizes.indices, mesh->indices);
        drawable.meshes.push_back(std::move(mesh));
    }
    DecodedTextures& textures = result->textures;
    textures = packed.shared;
    for (const PackedDrawable::OwnTexture& own : packed.own) {
        Texture texture;
        texture.wrap = own.wrap;
        if (own.channels == 0) {
            texture.image16 = Image16(own.width, own.height, 1);
            take(raw, offset, texture.image16.pixels.size(), texture.image16.pixels);
        } else {
            texture.image = Image8(own.width, own.height, own.channels);
            take(raw, offset, texture.image.pixels.size(), texture.image.pixels);
        }
        (own.space == ColorSpace::srgb ? textures.color : textures.linear)[std::size_t(own.index)] =
            std::make_shared<const MipTexture>(decode_texture(texture, own.space));
    }
    for (std::size_t b = 0; b < packed.meshes.size(); ++b) {
        Batch batch;
        batch.mesh = drawable.meshes[b].get();
        const int m = packed.batch_materials[b];
        if (m >= 0) batch.surface = material_surface(packed.materials[std::size_t(m)], textures);
        drawable.batches.push_back(batch);
        drawable.materials.push_back(m);
    }
    drawable.bounds = packed.bounds;
    return result;
}

std::size_t packed_size(const PackedDrawable& packed) {
    return packed.bytes.capacity() + packed.meshes.size() * sizeof(PackedDrawable::MeshSizes) +
           packed.own.size() * sizeof(PackedDrawable::OwnTexture) +
           packed.materials.size() * sizeof(Material) +
           (packed.shared.color.size() + packed.shared.linear.size()) *
               sizeof(std::shared_ptr<const MipTexture>);
}

}  // namespace boxlod
