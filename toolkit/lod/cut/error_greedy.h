// The error-driven level mode `error-greedy` (beyond the manual; docs/design.md:
// Level values and the cut). Start from the root's box and repeatedly open the
// boxed node whose opening buys the largest drop of estimated error per added
// byte; cutting that sequence of cuts at byte budgets spaced geometrically from
// the root's box to the original gives levels N..1.
//
// The error of a box is a proxy for its image error: the area-weighted depth of
// the sub-tree's surface behind the box's faces,
//   e(n) = sum over triangles t below n of area(t) x d(centroid(t), box surface)  [m^3],
// what parallax exposes when the flat face stands in for that surface.
// Opening n trades e(n) for its children's boxes' errors (its own geometry is
// exact) and the box's bytes for its own geometry's and the children's boxes'.
// Bytes as cost.h counts them; a box's as box_bytes_estimate at the sizing
// distance, so a level sized for a farther distance (a chain's, sized per
// level) sees cheaper boxes and opens fewer: each level's cut is the best for
// the distance it is drawn from. Levels from one session are nested.
#pragma once
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/pages/texture_sizing.h"

#include <optional>
#include <vector>

namespace boxlod {

// e(n) for every node with a box (0 for the others).
std::vector<double> box_depth_errors(const Model& model,
                                     const std::vector<std::optional<OrientedBox>>& boxes);

struct GreedyOpening {
    std::vector<int> order;     // nodes in the order they are opened, the root first
    std::vector<double> bytes;  // bytes[k]: the cut's bytes after k openings (bytes[0]: the root's box)
    std::vector<double> error;  // error[k]: the summed e of its boxes
};

// Deterministic: ties in the ratio go to the lower node index. Untextured
// boxes cost their mesh only.
GreedyOpening greedy_opening(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                             const TextureSizing& sizing, bool textured);

// Per level c = 1..N of budgets B_1..B_N (bytes), the openings it keeps: the
// longest prefix whose cut costs at most B_c, never fewer than a coarser
// level's, so levels nest. [0]: every opening (the original).
std::vector<std::size_t> greedy_prefixes(const GreedyOpening& opening, const std::vector<double>& budgets);

// Per node, the largest c whose prefix opens it (0: none of 1..N), as level values.
std::vector<int> opened_levels(const Model& model, const GreedyOpening& opening,
                               const std::vector<std::size_t>& prefixes);

// Level values from the opening: N = wanted_levels, budgets geometric from the
// root's box to the original (level_budgets.h: geometric_budgets).
LevelValues error_greedy_levels(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                                int wanted_levels, const TextureSizing& sizing, bool textured);

}  // namespace boxlod
