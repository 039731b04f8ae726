// What a model costs the engine that loads it (docs/design.md: Cost): draw calls, the
// bytes of its vertex and index buffers, and the bytes of its textures both
// uncompressed and in GPU block compression, each with its full mip chain.
#pragma once
#include "base/key_values.h"
#include "renderer/renderer.h"  // RenderMode, maps_drawn
#include "toolkit/model/model.h"
#include "toolkit/model/vertex_layout.h"  // primitive_mesh_bytes

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace boxlod {

// Block-compressed GPU formats (Direct3D 11 "Texture Block Compression";
// S3TC/RGTC/BPTC in OpenGL and Vulkan): every 4x4 texel block takes 8 bytes
// (BC1 colour with 1-bit alpha, BC4 one channel) or 16 (BC5 two channels,
// BC7 colour with full alpha).
enum class GpuFormat { bc1, bc4, bc5, bc7 };

struct ModelCost {
    std::uint64_t draw_calls = 0;  // one per material and vertex layout drawn (vertex_layout.h: DrawCallKey)
    std::uint64_t mesh_bytes = 0;  // vertex + index buffers as boxlod's glTF export writes them
    std::uint64_t texture_bytes =
        0;  // every texture a material uses, uncompressed at the format written, with mips
    std::uint64_t texture_bytes_gpu = 0;  // the same textures block-compressed, with mips
    std::uint64_t bytes() const { return mesh_bytes + texture_bytes_gpu; }
};

ModelCost model_cost(const Model& model);

// A cost in parts, for several models drawn together (a city's buildings at
// their levels): draw calls and meshes add up, while a texture is paid for
// once however many models use it, known by a digest of its texels.
struct TextureCost {
    TextureDigest digest;
    std::uint64_t bytes = 0, bytes_gpu = 0;
    unsigned maps = 0;  // bit 1 << MaterialMap for each map some material samples it as
};
struct CostParts {
    std::uint64_t draw_calls = 0, mesh_bytes = 0;
    std::vector<TextureCost> textures;  // every texture a material uses
};
CostParts cost_parts(const Model& model);
// By texture index, each texture `materials` sample (indices into the model's),
// in the use of the first material that samples it.
std::map<int, TextureCost> texture_costs(const Model& model, const std::set<int>& materials);
// Every texture counted: what the files hold (build, info, chains).
ModelCost combined_cost(const std::vector<const CostParts*>& parts);
// Only the textures of the maps `mode` draws (renderer.h: maps_drawn): what an
// engine drawing that way loads (sweeps, city frames). Meshes as exported.
ModelCost drawn_cost(const std::vector<const CostParts*>& parts, RenderMode mode);

// Texels of a full mip chain: level i is max(1, w >> i) x max(1, h >> i), down to 1 x 1.
std::uint64_t mip_chain_texels(int width, int height);
// Bytes of a full mip chain in `format`: ceil(w / 4) x ceil(h / 4) blocks per level.
std::uint64_t block_compressed_bytes(int width, int height, GpuFormat format);

// draw_calls, mesh_bytes, texture_bytes, texture_bytes_gpu, bytes, each name + `suffix` ("_lod", "_original",
// "").
KeyValues cost_entries(const ModelCost& cost, const std::string& suffix);

}  // namespace boxlod
