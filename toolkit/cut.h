// The cut (DESIGN.md: Level values and the cut): taken top-down from the
// root; a node with L(n) >= c keeps its own geometry and its children are
// visited; a node with L(n) < c is replaced with its whole sub-tree by its box.
// Beyond the manual, `keep_small_subtrees`: a sub-tree of at most 6 faces (its
// box's) keeps its geometry instead, so that no box costs more faces than it
// replaces (the manual's rule boxes single quads into 6 faces: the finest levels
// then draw more faces than the original).
#pragma once
#include "toolkit/model.h"

#include <optional>
#include <vector>

namespace boxlod {

struct Cut {
    std::vector<int> used_nodes;      // every node the cut visits, in tree order
    std::vector<int> geometry_nodes;  // used nodes that keep their own geometry
    std::vector<int> box_nodes;       // used nodes replaced by their box (sub-trees with geometry)
};

Cut take_cut(const Model& model, const std::vector<int>& level, int current_level,
             const std::vector<std::optional<OrientedBox>>& boxes, bool keep_small_subtrees = false);

// Faces (polygons as stored) of each node's whole sub-tree.
std::vector<std::size_t> subtree_faces(const Model& model);

}  // namespace boxlod
