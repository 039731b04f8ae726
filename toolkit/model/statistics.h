// The manual's Statistics block (docs/design.md: Statistics) for a model.
#pragma once
#include "base/key_values.h"
#include "toolkit/model/model.h"

namespace boxlod {

struct MeshCounts {
    std::size_t batches = 0;  // the manual's VBOs: one per material used
    std::size_t faces = 0;    // polygons as stored (a quad is one face)
    std::size_t triangles = 0;
    std::size_t vertices = 0;
};

MeshCounts mesh_counts(const Model& model);

// nodes, nodes_with_geometry, depth, *_original counts, mesh_width/height/depth.
KeyValues model_statistics(const Model& model);

}  // namespace boxlod
