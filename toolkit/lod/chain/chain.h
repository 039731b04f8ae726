// A chain of levels, as engines show them (docs/design.md: Files; docs/cost.md:
// Switching levels): level 0 the original, level c >= 1 sized for its own
// distance d_c (LodParameters::level_distances), so each level is as sharp
// as the screen where it is used. A session bakes for one distance, so the
// chain holds one per distance; boxes and hybrid's measurements are made
// once, by the first. Every command that makes more than one level (build,
// tiles, view) asks the chain for them, so level c is the same level
// whichever command, or however many levels, asked.
#pragma once
#include "toolkit/lod/chain/error_by_distance.h"
#include "toolkit/lod/cut/level_values.h"
#include "toolkit/lod/lod.h"
#include "toolkit/lod/lod_parameters.h"
#include "toolkit/lod/pages/boxes.h"
#include "toolkit/lod/pages/texture_sizing.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace boxlod {

struct HybridMeasurements;  // hybrid.h
struct LodSession;          // lod_session.h

// The doubling rule: level c >= 1 sized for level 1's distance x 2^(c-1)
// (docs/cost.md: Switching levels), at most parameter_range::distance's
// largest (64 levels double past it); level_distances caps it by budgets.
double doubled_distance(double level_one_distance, int level);

// The sizing distances of levels 1..N by `rule` from the (resolved) distance;
// empty for the rule `same`. With one budget a level, `auto` sizes level c no
// farther than distance x B_1 / B_c: a ladder finer than halvings would
// otherwise size its last levels where the building is under a pixel
// (docs/design.md: Texture sizing). Throws InputError naming level_distances
// when a list has not one distance per level.
std::vector<float> level_distances(const LevelDistances& rule, float distance, int levels,
                                   const std::vector<ByteBudget>& budgets = {});

// What a chain may be given beside its model and parameters.
struct ChainOptions {
    // The model's node_boxes for parameters.box_kind, computed once and reused (the sweep's variants).
    const std::vector<std::optional<OrientedBox>>* boxes = nullptr;
    bool budgets_strict = true;  // false (sweeps): a level no cut fits draws the coarsest instead of failing
};

// The sessions behind it (lod_session.h) are lod/'s own: whoever holds a
// chain asks it for levels, their sizing and their parameters. The non-const
// functions make a distance's session when first asked: one thread at a time.
struct Chain {
    const Model& model;
    int threads;
    std::shared_ptr<HybridMeasurements>
        measurements;                   // level mode hybrid: made once, reused at every distance
    std::unique_ptr<LodSession> first;  // at the parameters' distance; level 0, the boxes, the level values
    std::vector<float> distances;       // of levels 1..N; empty: every level at the first's distance
    std::map<float, std::unique_ptr<LodSession>> sized;
    LodTimes written;  // what the commands spend on the chain's previews and files (times() adds it)

    // Throws InputError for an LoD model, bad parameters, or a list of level distances that does not fit.
    Chain(const Model& model, const LodParameters& parameters, int threads, const ChainOptions& options = {});
    ~Chain();
    Chain(const Chain&) = delete;
    Chain& operator=(const Chain&) = delete;

    // The chain's parameters, distance resolved: what a level's parameter file
    // saves, so that building from it makes the same level.
    const LodParameters& parameters() const;
    int obtained_levels() const;
    const LevelValues& level_values() const;                       // of the first session
    const std::vector<std::optional<OrientedBox>>& boxes() const;  // per node (pages/boxes.h)
    LodSession& for_level(int level);                              // the session that sizes level `level`
    const LodParameters& sized_parameters(int level);              // level `level`'s: its sizing distance
    const TextureSizing& sizing(int level);                        // the texel sizing level `level` bakes at
    Lod build(int level);  // level `level` (0..obtained_levels(); InputError beyond)
    // The whole model as one baked proxy sized as level `level` (lod_builder.h: build_baked_model).
    Lod build_baked_model(const std::vector<Primitive>& geometry, int texel_scale, int level);
    LodTimes times() const;  // summed over every session and `written`
};

// A level as the chain holds it.
struct ChainLevel {
    int level = 0;
    Lod lod;
    std::vector<int>
        same_levels;  // the later levels that draw what it draws (model.h: draws_the_same), left out
};

// Throws InputError when a level's byte budget lies below its session's
// coarsest cut: called before anything is written, a refused chain leaves nothing.
void check_chain_budgets(Chain& chain, const std::vector<int>& levels);

// Builds levels first..last in order and hands each distinct one to `take`
// (in order, once the next distinct level is known), at most `max_levels` of
// them. Returns the first level not held: last + 1, or where the cap cut.
int take_distinct_levels(Chain& chain, int first, int last, int max_levels,
                         const std::function<void(ChainLevel)>& take);

// A chain as engines get it: the levels some distance draws, each with the
// distance it switches in at (level 0: 0).
struct SwitchedChain {
    std::vector<ChainLevel> levels;
    std::vector<double> switch_distances;
    // Measured (a threshold given): the distances, and each level's error at them.
    std::vector<double> distances;
    std::vector<std::vector<double>> errors;
    int distinct = 0, reachable = 0;  // the chain's distinct levels, and those some distance draws
};

// Every distinct level, then those that some distance draws, each cheaper
// than the one before (error_by_distance.h: reachable_levels), the `max_levels`
// finest of them. Switch distances from the error measured by distance
// within `threshold` (> 0), or where a level's texels meet the screen's
// pixels, its sizing distance (0).
SwitchedChain switched_levels(Chain& chain, double threshold, int max_levels);

}  // namespace boxlod
