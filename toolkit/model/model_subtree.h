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

}  // namespace boxlod
