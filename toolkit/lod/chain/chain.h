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
#include "toolkit/lod/lod_builder.h"

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace boxlod {

// The doubling rule: level c >= 1 sized for level 1's distance x 2^(c-1)
// (docs/cost.md: Switching levels), at most parameter_range::distance's
// largest (64 levels double past it).
double doubled_distance(double level_one_distance, int level);

// The sizing distances of levels 1..N by `rule` from the (resolved) distance;
// empty for the rule `same`. Throws InputError naming level_distances when a
// list has not one distance per level.
std::vector<float> level_distances(const LevelDistances& rule, float distance, int levels);

struct Chain {
    const Model& model;
    int threads;
    std::shared_ptr<HybridMeasurements>
        measurements;                   // level mode hybrid: made once, reused at every distance
    std::unique_ptr<LodSession> first;  // at the parameters' distance; level 0, the boxes, the level values
    std::vector<float> distances;       // of levels 1..N; empty: every level at the first's distance
    std::map<float, std::unique_ptr<LodSession>> sized;

    Chain(const Model& model, const LodParameters& parameters, int threads);
    // The chain's parameters, distance resolved: what a level's parameter file
    // saves, so that building from it makes the same level.
    const LodParameters& parameters() const { return first->input.parameters; }
    int obtained_levels() const { return first->derived.levels.obtained_levels; }
    LodSession& for_level(int level);  // the session that sizes level `level`
    LodTimes times() const;            // summed over every session
};

// A level as the chain holds it.
struct ChainLevel {
    int level = 0;
    Lod lod;
    LodSession* session = nullptr;  // the one that sized it
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
