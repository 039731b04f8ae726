// Level values (docs/design.md: Level values and the cut; the manual's Geometry
// section): every node n gets L(n) in 0..N-1; at current level c a node with
// L(n) < c is replaced, with its sub-tree, by its box.
#pragma once
#include "base/enum_table.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/model.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

enum class LevelMode {
    top_down,            // N = depth + 1; L(root) = N - 1; L(child) = L(parent) - 1
    bottom_up,           // L(leaf) = 0; L(inner) = 1 + max over children
    bottom_up_siblings,  // bottom-up, siblings raised to their maximum before the parent
    box_volume,          // box modes: L = floor(t * (N - 1)), t from the box value v
    box_area,
    box_diagonal,
    box_max_extent,
    error_greedy,  // beyond the manual: open the node that buys the most estimated error per byte
                   // (error_greedy.h)
    hybrid,  // beyond the manual: per node a box, a simplified sub-tree or its geometry, by measured error
             // per byte (hybrid.h)
};
enum class Interpolation { linear, log, rank };  // how box modes turn v into t

std::span<const EnumEntry<LevelMode>> level_modes();  // names ("top-down", ...) and help
std::span<const EnumEntry<Interpolation>> interpolations();
bool parse_level_mode(const std::string& name, LevelMode& mode);
const char* level_mode_name(LevelMode mode);
bool parse_interpolation(const std::string& name, Interpolation& interpolation);
const char* interpolation_name(Interpolation interpolation);
bool is_box_mode(LevelMode mode);
bool uses_boxes(LevelMode mode);  // the box modes, error-greedy and hybrid
bool orders_by_bytes(
    LevelMode mode);  // error-greedy and hybrid: their levels can take byte budgets (level_budgets.h)

struct LevelValues {
    std::vector<int> level;   // per node
    int obtained_levels = 1;  // N
};

// The level values of the hierarchy modes, and of the box modes from `boxes`
// (from node_boxes; nodes without a box take no part in vmin/vmax and get
// level 0; N = wanted_levels). Every mode at once: level_values.h.
LevelValues top_down_levels(const Model& model);
LevelValues bottom_up_levels(const Model& model, bool same_siblings);
LevelValues box_mode_levels(const Model& model, LevelMode mode, int wanted_levels,
                            Interpolation interpolation,
                            const std::vector<std::optional<OrientedBox>>& boxes);

}  // namespace boxlod
