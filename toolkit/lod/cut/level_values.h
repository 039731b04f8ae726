// Every node's level value for any level mode (docs/design.md: Level values
// and the cut): the hierarchy and box modes of level_modes.h and error-greedy
// (error_greedy.h) behind one call. Above both, so neither includes the other.
#pragma once
#include "toolkit/lod/cut/level_modes.h"

namespace boxlod {

// `boxes` (from node_boxes) is used by the box modes and error-greedy; nodes
// without a box take no part in vmin/vmax and get level 0. `wanted_levels` is N
// for both. error-greedy prices boxes with `sizing` (its distance aside) and
// `textured`. hybrid's levels come from its plan, which renders (hybrid.h:
// hybrid_levels; start_lod makes it): not here.
LevelValues compute_level_values(const Model& model, LevelMode mode, int wanted_levels,
                                 Interpolation interpolation,
                                 const std::vector<std::optional<OrientedBox>>& boxes,
                                 const TextureSizing& sizing = {}, bool textured = true);

// N alone: the wanted levels for the modes that take them (box modes,
// error-greedy, hybrid), the hierarchy's for the others.
int obtained_levels(const Model& model, LevelMode mode, int wanted_levels);

}  // namespace boxlod
