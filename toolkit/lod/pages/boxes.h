// The box that replaces a node's sub-tree in an LoD (docs/design.md: Boxes).
#pragma once
#include "base/enum_table.h"
#include "toolkit/model/model.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

enum class BoxKind {
    scope,     // the grammar's scope as stored (may be smaller than the geometry)
    expanded,  // the scope's orientation, grown just enough to enclose the sub-tree's geometry
    minimal,   // CGAL's optimal (minimum-volume) OBB of the sub-tree's vertices, fixed seed
};
std::span<const EnumEntry<BoxKind>> box_kinds();  // names ("scope", ...) and help
bool parse_box_kind(const std::string& name, BoxKind& kind);
const char* box_kind_name(BoxKind kind);

// One box per node for its whole sub-tree; std::nullopt where the sub-tree has
// no geometry. Nodes without a scope use `minimal` for `scope` and `expanded`.
// Degenerate geometry (< 4 points, flat, collinear) still gets a valid box with
// a small positive thickness. Deterministic for any thread count.
std::vector<std::optional<OrientedBox>> node_boxes(const Model& model, BoxKind kind, int threads);

// What node_boxes did for the minimal boxes: the orientation of each distinct
// sub-tree hull, up to translation, is solved once; nodes with an equal hull
// (a parent whose only geometry is one child's, a translated copy) reuse it
// exactly, as the seed comes from the hull's shape.
struct MinimalBoxCounts {
    std::size_t nodes = 0;     // nodes that needed a minimal box
    std::size_t computed = 0;  // distinct hull shapes solved (CGAL, or a flat/collinear/point case)
    std::size_t reused = 0;    // nodes that took an equal shape's orientation
};
std::vector<std::optional<OrientedBox>> node_boxes(const Model& model, BoxKind kind, int threads,
                                                   MinimalBoxCounts& counts);

// Volume, surface area, diagonal, longest side (full extents, not half).
float box_volume(const OrientedBox& box);
float box_area(const OrientedBox& box);
float box_diagonal(const OrientedBox& box);
float box_max_extent(const OrientedBox& box);

}  // namespace boxlod
