#pragma once
// A group of a sweep's rows: one drawn candidate (an LoD level, a baseline's mesh) over views x
// distances x render modes, each row rendered and compared with the original's render of its
// view (made once per model). Private to the sweep (sweep.cpp plans, sweep_baselines.cpp adds
// the baselines' groups).

#include "experiments/sweep/sweep_config.h"
#include "experiments/sweep/sweep_report.h"
#include "experiments/sweep/sweep_tables.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/pages/atlas.h"
#include "toolkit/metrics/shot.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/framing.h"

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace boxlod {

// What one group of rows draws: an LoD level or a baseline mesh.
struct SweepCandidate {
    Model model;
    Atlas atlas;                    // pages = 0 for untextured boxes and the baselines
    std::uint64_t face_texels = 0;  // the baked faces' own texels, without the atlas's gutters and free space
    std::size_t nodes_with_box = 0;
    std::string depth_error;  // an LoD's proxy error (LodDerived::depth_errors summed over its boxes); empty
                              // for baselines
    std::string
        measured_error;  // a hybrid level's measured proxy error (Lod::measured_error); empty for the others
    int obtained_levels = 0;
    CostParts cost;                           // each row states the cost of the maps its render mode draws
    std::unique_ptr<DrawableModel> drawable;  // made by run_group unless `make` made it
    double seconds = 0;                       // building it and making it drawable
    std::string variant;                      // a baseline's variant (results.csv baseline_variant)
};

// `cost`: the model's, when its builder has it already (an LoD); else computed here.
SweepCandidate candidate(Model model, Atlas atlas, std::size_t nodes_with_box, int obtained_levels,
                         const CostParts* cost = nullptr);

// A level mode x box kind x interpolation of the plan, with the levels the sweep draws.
struct SweepVariant {
    LevelMode mode;
    BoxKind box;
    Interpolation interpolation;
    int obtained_levels = 1;
    std::vector<int> levels;
};

// The executor's state for one model: the original's renders (per view,
// distance and mode, made when first needed) and the progress counters.
struct ModelRun {
    const SweepConfig& config;
    const SweepModel& entry;
    const Model& model;
    Framing framing;
    std::size_t index = 0, rows = 0, done = 0, computed = 0;
    double seconds = 0;
    int threads = 0;
    std::FILE* progress = nullptr;
    std::unique_ptr<DrawableModel> original = nullptr;
    std::map<std::tuple<std::size_t, std::size_t, RenderMode>, Shot> references = {};
};

// Rows per group: views x distances x render modes.
std::size_t rows_per_group(const SweepConfig& config);

// A group: the rows of one drawn candidate (an LoD level, a simplified mesh, the single box)
// over views x distances x render modes. `slot(mode, view, distance)` says which rows may
// share one candidate, `make(slot, alternative)` builds it; both run only for rows missing
// from results.csv.
// With several `alternatives` (simplification-best), each is drawn for every missing row
// and the group keeps the one with the lowest mean choice_error over them, of
// those within `budget` bytes (every texture) where there are any.
void run_group(ModelRun& run, SweepOutput& out, SweepReport& report, const std::string& group,
               const std::function<int(RenderMode, std::size_t, std::size_t)>& slot,
               const std::function<SweepCandidate(int, int)>& make, int alternatives = 1, double budget = -1);

}  // namespace boxlod
