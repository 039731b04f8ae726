#include "toolkit/lod/cut/level_modes.h"

#include "base/input_error.h"
#include "toolkit/lod/pages/boxes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boxlod {

namespace {

constexpr EnumEntry<LevelMode> level_mode_table[] = {
    {LevelMode::top_down, "top-down",
     "the root gets N - 1, each child its parent's value - 1; N = depth + 1"},
    {LevelMode::bottom_up, "bottom-up", "leaves 0, inner nodes 1 + their children's maximum"},
    {LevelMode::bottom_up_siblings, "bottom-up-siblings",
     "bottom-up, siblings raised to their maximum first"},
    {LevelMode::box_volume, "box-volume", "from the box's volume, N = the wanted levels"},
    {LevelMode::box_area, "box-area", "from the box's surface area"},
    {LevelMode::box_diagonal, "box-diagonal", "from the box's diagonal"},
    {LevelMode::box_max_extent, "box-max-extent", "from the box's longest side"},
    {LevelMode::error_greedy, "error-greedy",
     "beyond the manual: from the root's box, open the node that buys the most estimated error per byte; N = "
     "the wanted levels, at byte budgets from the root's box to the original"},
    {LevelMode::hybrid, "hybrid",
     "beyond the manual: per node its box, its sub-tree simplified or its geometry, chosen by measured image "
     "error per byte from the root's cheapest proxy; N = the wanted levels, budgets as error-greedy's"},
};

constexpr EnumEntry<Interpolation> interpolation_table[] = {
    {Interpolation::linear, "linear", "the box value v itself"},
    {Interpolation::log, "log", "log v"},
    {Interpolation::rank, "rank", "the rank of v among the nodes"},
};

}  // namespace

// Hierarchy, Top-Down: the root gets N - 1, each child its parent's value - 1.
LevelValues top_down_levels(const Model& model) {
    LevelValues values;
    values.obtained_levels = tree_depth(model) + 1;
    values.level.assign(model.nodes.size(), values.obtained_levels - 1);
    for (std::size_t i = 1; i < model.nodes.size(); ++i)
        values.level[i] = values.level[model.nodes[i].parent] - 1;
    return values;
}

// Hierarchy, Bottom-Up: leaves 0, inner nodes 1 + the children's maximum. With
// `same_siblings`, a node's children are first raised to their maximum. Children
// follow their parents, so a backward pass sees every child's final value first.
LevelValues bottom_up_levels(const Model& model, bool same_siblings) {
    LevelValues values;
    values.level.assign(model.nodes.size(), 0);
    for (std::size_t i = model.nodes.size(); i-- > 0;) {
        const std::vector<int>& children = model.nodes[i].children;
        if (children.empty()) continue;
        int highest = 0;
        for (int child : children) highest = std::max(highest, values.level[child]);
        if (same_siblings)
            for (int child : children) values.level[child] = highest;
        values.level[i] = highest + 1;
    }
    values.obtained_levels = values.level[0] + 1;
    return values;
}

namespace {

double box_value(LevelMode mode, const OrientedBox& box) {
    switch (mode) {
    case LevelMode::box_volume: return box_volume(box);
    case LevelMode::box_area: return box_area(box);
    case LevelMode::box_diagonal: return box_diagonal(box);
    default: return box_max_extent(box);
    }
}

// The interpolated value whose range maps to t in 0..1: v itself, log v, or
// the rank of v (ties share the lowest rank).
std::vector<double> interpolated(std::vector<double> v, Interpolation interpolation) {
    if (interpolation == Interpolation::log) {
        const double floor = 1e-30;  // log of a zero-size box stays finite
        for (double& x : v) x = std::log(std::max(x, floor));
    } else if (interpolation == Interpolation::rank) {
        std::vector<double> sorted = v;
        std::sort(sorted.begin(), sorted.end());
        for (double& x : v) x = double(std::lower_bound(sorted.begin(), sorted.end(), x) - sorted.begin());
    }
    return v;
}

}  // namespace

// Bounding Box modes: t = (w - wmin) / (wmax - wmin) over the boxed nodes (1
// when the range is empty), L = floor(t * (N - 1)) with N the wanted levels.
// For rank, wmin = 0 and wmax = count - 1, so t = rank / (count - 1).
LevelValues box_mode_levels(const Model& model, LevelMode mode, int wanted_levels,
                            Interpolation interpolation,
                            const std::vector<std::optional<OrientedBox>>& boxes) {
    if (boxes.size() != model.nodes.size())
        throw std::invalid_argument("compute_level_values: one box (or none) per node expected");
    std::vector<int> boxed;
    std::vector<double> v;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (boxes[i]) {
            boxed.push_back(int(i));
            v.push_back(box_value(mode, *boxes[i]));
        }
    std::vector<double> w = interpolated(v, interpolation);
    double lo = 0, hi = 0;
    if (interpolation == Interpolation::rank) {
        hi = double(w.size()) - 1;
    } else if (!w.empty()) {
        lo = *std::min_element(w.begin(), w.end());
        hi = *std::max_element(w.begin(), w.end());
    }
    LevelValues values;
    values.obtained_levels = wanted_levels;
    values.level.assign(model.nodes.size(), 0);
    // All v equal: every t is 1 (for rank too, where all ranks would be 0).
    const bool empty_range =
        v.empty() || *std::min_element(v.begin(), v.end()) == *std::max_element(v.begin(), v.end());
    for (std::size_t k = 0; k < boxed.size(); ++k) {
        double t = empty_range || hi <= lo ? 1.0 : (w[k] - lo) / (hi - lo);
        int level = int(std::floor(t * (wanted_levels - 1)));
        values.level[boxed[k]] = std::clamp(level, 0, wanted_levels - 1);
    }
    return values;
}

std::span<const EnumEntry<LevelMode>> level_modes() { return level_mode_table; }
std::span<const EnumEntry<Interpolation>> interpolations() { return interpolation_table; }
bool parse_level_mode(const std::string& name, LevelMode& mode) {
    return parse_enum(level_modes(), name, mode);
}
const char* level_mode_name(LevelMode mode) { return enum_name(level_modes(), mode); }
bool parse_interpolation(const std::string& name, Interpolation& value) {
    return parse_enum(interpolations(), name, value);
}
const char* interpolation_name(Interpolation value) { return enum_name(interpolations(), value); }

bool is_box_mode(LevelMode mode) {
    return mode == LevelMode::box_volume || mode == LevelMode::box_area || mode == LevelMode::box_diagonal ||
           mode == LevelMode::box_max_extent;
}

bool orders_by_bytes(LevelMode mode) { return mode == LevelMode::error_greedy || mode == LevelMode::hybrid; }

bool uses_boxes(LevelMode mode) { return is_box_mode(mode) || orders_by_bytes(mode); }

}  // namespace boxlod
