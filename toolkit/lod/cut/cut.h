// The cut (docs/design.md: Level values and the cut): taken top-down from the
// root; a node with L(n) >= c keeps its own geometry and its children are
// visited; a node with L(n) < c is replaced with its whole sub-tree by its box.
// Beyond the manual, a node marked in `kept` (kept_subtrees.h marks whole
// sub-trees) is treated as if L(n) >= c: it keeps its own geometry and its
// children are visited.
#pragma once
#include "toolkit/model/model.h"

#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace boxlod {

// A node drawn by a baked proxy (baked_proxy.h): a simplified geometry of its
// sub-tree (positions; simplification.h: geometry_only) sampling its box's baked faces.
struct BakedNode {
    int node = 0;
    int proxy = -1;  // hybrid.h: its proxy in the plan; -1: none (the proxy-baked baseline)
    const std::vector<Primitive>* geometry =
        nullptr;  // the plan's or the caller's, while a level is built (then null)
};

struct Cut {
    std::vector<int> used_nodes;      // every node the cut visits, in tree order
    std::vector<int> geometry_nodes;  // used nodes that keep their own geometry
    std::vector<int> box_nodes;       // used nodes replaced by their box (sub-trees with geometry)
    std::vector<std::pair<int, int>>
        simplified_nodes;  // hybrid.h: (used node, its simplified proxy in the plan)
    std::vector<BakedNode> baked_nodes;
    // hybrid.h: box and baked nodes whose texels are as at s > 1 times the sizing
    // distance (texture_sizing.h), with s; every other's s is 1.
    std::map<int, int> box_texel_scales;
};

// The texel scale of box node n in the cut (1 unless box_texel_scales says otherwise).
int texel_scale(const Cut& cut, int n);

Cut take_cut(const Model& model, const std::vector<int>& level, int current_level,
             const std::vector<std::optional<OrientedBox>>& boxes, const std::vector<bool>& kept = {});

}  // namespace boxlod
