// A model made ready for the renderer: its geometry merged into one mesh per
// material (the manual's VBOs), its textures decoded once for sampling.
#pragma once
#include "renderer/renderer.h"
#include "toolkit/model/model.h"

#include <memory>
#include <span>

namespace boxlod {

// Every texture the materials use, decoded as they use it: colour as sRGB,
// normal and height maps as linear data. Read-only once made, so many
// drawables (one per baked box) can share it across threads.
struct DecodedTextures {
    std::vector<std::shared_ptr<const MipTexture>> color, linear;  // per model texture; null where unused
};

// Decoded textures shared by content between models: a city's buildings and
// every level of their LoDs use the same few grammar textures, each copied
// into each model. Equal images (by a 128-bit digest of their texels) decode once.
// Thread-safe; entries live as long as the cache or a DecodedTextures using them.
class TextureCache {
public:
    TextureCache();
    ~TextureCache();
    std::shared_ptr<const MipTexture> decode(const Texture& texture, ColorSpace space);
    std::shared_ptr<const MipTexture> find(const Texture& texture,
                                           ColorSpace space) const;  // null if not decoded yet
    std::size_t size() const;                                        // distinct decoded textures

private:
    struct Entries;
    std::unique_ptr<Entries> entries_;
};

// One texture as a material reads it (colour maps as sRGB, normal and height maps as linear data).
MipTexture decode_texture(const Texture& texture, ColorSpace space);

// The textures materials read, each once per colour space: (texture index, space)
// in the order the materials first use them.
std::vector<std::pair<int, ColorSpace>> textures_read(const std::vector<Material>& materials);

// `threads` as parallel_for's (0: all cores).
DecodedTextures decode_textures(const Model& model, TextureCache* cache = nullptr, int threads = 1);

struct Drawable {
    std::vector<std::unique_ptr<Mesh>> meshes;
    std::vector<Batch> batches;  // point into meshes and the DecodedTextures
    std::vector<int> materials;  // per batch: the model's material it draws (-1: none)
    Bounds bounds;
};

// How a material draws, its textures taken from `textures`.
Surface material_surface(const Material& material, const DecodedTextures& textures);

// The geometry of the sub-tree under `root` (the whole model by default).
Drawable make_drawable(const Model& model, const DecodedTextures& textures, int root = 0);
// Any primitives drawn with `materials` (a sub-tree's proxy: hybrid.h).
Drawable make_drawable(const std::vector<Material>& materials, const DecodedTextures& textures,
                       std::span<const Primitive* const> primitives);

// A model with its own textures, for commands that just draw it.
struct DrawableModel {
    DecodedTextures textures;
    Drawable drawable;
};
std::unique_ptr<DrawableModel> make_drawable_model(const Model& model, TextureCache* cache = nullptr,
                                                   int threads = 1);

}  // namespace boxlod
