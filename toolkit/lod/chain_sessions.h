// The sessions behind a chain of levels: level c >= 1 baked for its own sizing
// distance d_c (--level-distances; auto: d_c = d x 2^(c-1), the model's sizing
// distance d doubled per level, so each level is as sharp as the screen where
// it is used: docs/cost.md, Switching levels). A session bakes for one
// distance, so there is one per distance; boxes and level values are computed
// once, by the first.
#pragma once
#include "toolkit/lod/lod_builder.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace boxlod {

// The distances of levels 1..N from "auto" (at most parameter_range::distance's
// largest) or "D1,...,DN" (ascending, each within that range and at least
// 1 mm); throws InputError naming --level-distances.
std::vector<float> level_distances(const std::string& text, float distance, int levels);

struct ChainSessions {
    const Model& model;
    int threads;
    std::shared_ptr<HybridMeasurements> measurements;  // level mode hybrid: made once, reused at every distance
    std::unique_ptr<LodSession> first;  // at the parameters' distance; level 0 and its boxes
    std::vector<float> distances;       // of levels 1..N; empty: every level at the first's distance
    std::map<float, std::unique_ptr<LodSession>> sized;

    ChainSessions(const Model& model, const LodParameters& parameters, int threads);
    int obtained_levels() const { return first->derived.levels.obtained_levels; }
    LodSession& for_level(int level);
    LodTimes times() const;  // summed over every session
};

}  // namespace boxlod
