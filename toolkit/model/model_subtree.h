// Part of a model as a model of its own: a sub-tree with the materials and
// textures it uses (and no others), e.g. one building of a generated city, so
// that it can get its own LoD.
#pragma once
#include "toolkit/model/model.h"

#include <map>
#include <vector>

namespace boxlod {

// Copies materials, and the textures they use, from `source` into `out` on first
// use; returns the new index (-1 stays -1). New indices follow first use, so the
// same walk gives the same model.
struct MaterialCopier {
    const Model& source;
    Model& out;
    std::map<int, int> materials = {}, textures = {};

    int material(int index);
    int texture(int index);
};

// The nodes of the sub-tree under `root`, in index order (for the root: every node).
std::vector<int> subtree_nodes(const Model& model, int root);

// The sub-tree under `root` (names, rules, scopes, geometry, instance_of), root first;
// `source` is kept.
Model extract_subtree(const Model& model, int root);

// The objects of a city model (a CityJSON district's Buildings, a generated
// city's lots): each child of the root that draws a triangle of non-zero area
// below it (one scaled to nothing is no object); the root's own geometry (-1)
// besides them (a ground under the buildings), or the whole model (0) where it
// is all on the root (a single building from a file).
std::vector<int> object_nodes(const Model& city);
// Object `node` of object_nodes as a model of its own.
Model object_model(const Model& city, int node);

}  // namespace boxlod
