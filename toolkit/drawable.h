// A model made ready for the renderer: its geometry merged into one mesh per
// material (the manual's VBOs) and its textures decoded for sampling.
#pragma once
#include "renderer/renderer.h"
#include "toolkit/model.h"

#include <memory>

namespace boxlod {

struct Drawable {
    std::vector<std::unique_ptr<Mesh>> meshes;
    std::vector<std::unique_ptr<MipTexture>> textures;
    std::vector<Batch> batches;  // point into meshes and textures
    Bounds bounds;
};

Drawable make_drawable(const Model& model);

}  // namespace boxlod
