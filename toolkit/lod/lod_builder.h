// Building an LoD (the manual's CGA section): boxes and level values once per
// model; per current level the cut, baking of the boxes not baked before,
// atlas packing and the LoD mesh (kept original nodes + textured box quads).
#pragma once
#include "base/key_values.h"
#include "toolkit/lod/atlas.h"
#include "toolkit/lod/bake.h"
#include "toolkit/model/cost.h"
#include "toolkit/lod/cut.h"
#include "toolkit/lod/error_greedy.h"
#include "toolkit/lod/hybrid.h"
#include "toolkit/lod/level_pages.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/lod/texture_sizing.h"

#include <map>
#include <memory>

namespace boxlod {

struct LodTimes {  // seconds, for the time split in docs/performance.md
    double boxes = 0, levels = 0, bake = 0, pack = 0, mesh = 0, write = 0;  // write: preview + files
};

// What the user gave: the model and its parameters.
struct LodInput {
    const Model* model = nullptr;
    LodParameters parameters;  // distance resolved (never 0 here), model named
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
    std::shared_ptr<const HybridPlan> hybrid;      // level mode hybrid: the plan its levels are prefixes of
    std::shared_ptr<const GreedyOpening> opening;  // error-greedy with budgets: the openings its levels are prefixes of
    ModelCost original_cost;
};

// What changes as levels are built: the faces baked so far (once for all
// levels), and each budgeted level's prefix of the plan, start_lod's
// estimate until build_lod fits it to the level's real bytes.
struct LodCache {
    std::map<std::pair<int, int>, std::array<BakedFace, 6>> baked;  // per box node and texel scale (cut.h)
    std::vector<HybridLevel> hybrid_levels;  // hybrid: per current level c, its state
    std::vector<std::size_t> opening_steps;  // error-greedy with budgets: per level c, the openings drawn
};

// What every level of one model shares.
struct LodSession {
    LodInput input;
    LodDerived derived;
    LodCache cache;
    LodTimes times;
};

// Throws InputError for an LoD model (boxlod does not simplify its own output) or bad parameters.
// `boxes`, when given, are the model's node_boxes for parameters.box_kind (computed once, reused).
// `measurements`, when given, are shared with the sessions of the same model at
// other distances (level mode hybrid: chain.h).
std::unique_ptr<LodSession> start_lod(const Model& model, const LodParameters& parameters, int threads,
                                      const std::vector<std::optional<OrientedBox>>* boxes = nullptr,
                                      HybridMeasurements* measurements = nullptr);

struct Lod {
    int current_level = 0;
    // is_lod and lod_params set; the pages' textures (lod_page) and materials come first.
    Model model;
    Cut cut;
    Atlas atlas;  // no pages in untextured mode (no baking)
    std::uint64_t face_texels = 0;  // the packed faces' own texels (cropped), without gutters and free page space
    double depth_error = 0;  // the proxy error of the cut: e(n) summed over its boxes (error_greedy.h), m^3
    double measured_error = 0;  // hybrid: its proxies' measured errors summed (hybrid_cut_error), sizing-view pixels
    CostParts cost;  // of `model` (docs/design.md: Cost), computed once for the statistics and whoever draws it
    KeyValues statistics;  // docs/design.md: Statistics
};

Lod build_lod(LodSession& session, int current_level, int threads);

// Throws InputError when level c's byte budget lies below the real bytes of
// the session's coarsest cut, where build_lod would fail: a command calls it
// before it writes any level, so a refused build leaves nothing behind.
void check_budget_reachable(LodSession& session, int level, int threads);

}  // namespace boxlod
