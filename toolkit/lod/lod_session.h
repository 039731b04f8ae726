// What every level of one model shares while it is built (lod_builder.h):
// the input, what is derived from it once, the faces baked so far and the
// time spent, apart from the builder so the steps of a level (level_faces.h)
// read it without depending on the builder.
#pragma once
#include "base/memory_budget.h"
#include "toolkit/lod/cut/error_greedy.h"
#include "toolkit/lod/cut/level_values.h"
#include "toolkit/lod/hybrid/hybrid.h"
#include "toolkit/lod/lod.h"
#include "toolkit/lod/lod_parameters.h"
#include "toolkit/lod/pages/bake.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/cost.h"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace boxlod {

// What the user gave: the model and its parameters.
struct LodInput {
    const Model* model = nullptr;
    LodParameters parameters;    // distance resolved (never 0 here), model named
    bool budgets_strict = true;  // false (sweeps): a level no cut fits draws the coarsest instead of failing
};

// What start_lod derives once from the input, read by every level.
struct LodDerived {
    DecodedTextures textures;
    std::vector<std::optional<OrientedBox>> boxes;
    std::vector<double> depth_errors;  // per node with a box, error_greedy.h's proxy e(n) in m^3
    LevelValues levels;
    TextureSizing sizing;
    std::vector<bool> kept;  // nodes keeping their geometry below their level (kept_subtrees.h); empty: none
    std::shared_ptr<const HybridPlan> hybrid;  // level mode hybrid: the plan its levels are prefixes of
    std::shared_ptr<const GreedyOpening>
        opening;  // error-greedy with budgets: the openings its levels are prefixes of
    ModelCost original_cost;
};

// What changes as levels are built: the faces baked so far (once for all
// levels), and each budgeted level's prefix of the plan, start_lod's
// estimate until build_lod fits it to the level's real bytes.
struct LodCache {
    std::map<std::pair<int, int>, std::array<BakedFace, 6>> baked;  // per box node and texel scale (cut.h)
    std::vector<HybridLevel> hybrid_levels;                         // hybrid: per current level c, its state
    std::vector<std::size_t> opening_steps;  // error-greedy with budgets: per level c, the openings drawn
    MemoryHold baked_held;                   // `baked`'s bytes, counted by every memory check (level_faces.h)
};

// What every level of one model shares.
struct LodSession {
    LodInput input;
    LodDerived derived;
    LodCache cache;
    LodTimes times;
};

}  // namespace boxlod
