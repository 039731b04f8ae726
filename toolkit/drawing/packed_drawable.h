// A drawable model kept compressed until it is drawn (docs/city.md: Memory).
// A city of 1,000 buildings has about 9,000 levels; decoded, their meshes
// and mip-mapped pages need about 11 GB. Packed, a level keeps its meshes and
// its own textures' texels deflated (libdeflate level 1: fast, and baked
// pages are mostly free space), while textures a shared TextureCache already
// holds (a city's grammar textures) stay decoded and shared. Unpacking gives
// what make_drawable_model gives, so renders are byte-identical.
#pragma once
#include "toolkit/drawing/drawable.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace boxlod {

struct PackedDrawable {
    struct MeshSizes {
        std::size_t positions = 0, normals = 0, uvs = 0, tangents = 0, indices = 0;
    };
    struct OwnTexture {  // a texture whose texels are in `bytes`
        int index = 0;   // in the model's textures
        ColorSpace space = ColorSpace::srgb;
        int width = 0, height = 0, channels = 0;  // channels 0: a 16-bit single-channel image
        Wrap wrap = Wrap::repeat;
    };
    std::vector<MeshSizes> meshes;  // one per batch, in batch order
    std::vector<int> batch_materials;
    std::vector<Material> materials;
    DecodedTextures shared;  // sized like the model's textures; the shared ones set
    std::vector<OwnTexture> own;
    Bounds bounds;
    std::vector<std::uint8_t> bytes;  // the meshes' arrays, then the own textures' texels, deflated
    std::size_t raw_size = 0;         // of `bytes` inflated
    std::size_t unpacked_size = 0;    // what an unpacked copy holds: meshes and own mip chains
};

// `shared` may be null (nothing shared). Without `height_maps` the materials
// lose their height maps, which only parallax and POM read.
PackedDrawable pack_drawable(const Model& model, const TextureCache* shared, bool height_maps = true);
std::unique_ptr<DrawableModel> unpack_drawable(const PackedDrawable& packed);

// Bytes the packed form itself holds (its compressed stream and tables), without the shared textures.
std::size_t packed_size(const PackedDrawable& packed);

}  // namespace boxlod
