#include "toolkit/lod/cut/level_values.h"

#include "base/input_error.h"
#include "toolkit/lod/cut/error_greedy.h"

#include <stdexcept>
#include <string>

namespace boxlod {

LevelValues compute_level_values(const Model& model, LevelMode mode, int wanted_levels,
                                 Interpolation interpolation,
                                 const std::vector<std::optional<OrientedBox>>& boxes,
                                 const TextureSizing& sizing, bool textured) {
    if (model.nodes.empty()) throw InputError(model.source + ": the model has no nodes");
    switch (mode) {
    case LevelMode::top_down: return top_down_levels(model);
    case LevelMode::bottom_up: return bottom_up_levels(model, false);
    case LevelMode::bottom_up_siblings: return bottom_up_levels(model, true);
    default: break;
    }
    if (wanted_levels < 1)
        throw InputError("wanted levels must be at least 1, got " + std::to_string(wanted_levels));
    if (mode == LevelMode::error_greedy) {
        if (boxes.size() != model.nodes.size())
            throw std::invalid_argument("compute_level_values: one box (or none) per node expected");
        return error_greedy_levels(model, boxes, wanted_levels, sizing, textured);
    }
    if (mode == LevelMode::hybrid)
        throw std::logic_error("compute_level_values: hybrid levels come from start_lod's plan");
    return box_mode_levels(model, mode, wanted_levels, interpolation, boxes);
}

int obtained_levels(const Model& model, LevelMode mode, int wanted_levels) {
    if (uses_boxes(mode)) return wanted_levels;
    return compute_level_values(model, mode, wanted_levels, Interpolation::linear, {}).obtained_levels;
}

}  // namespace boxlod
