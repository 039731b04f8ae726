#pragma once
// The baselines' groups of a sweep's rows: the same rows as the first variant's levels, drawn by
// meshes that depend on no view, distance or mode (simplification, cgal, single box, file LoDs) or
// by the impostor and baked proxies (docs/sweeps.md).

#include "experiments/sweep/sweep_group.h"

namespace boxlod {

// The groups of the config's baselines, in the table's order; a level's triangles and budget are
// those of the first variant's level (its first row in `out`).
void run_baselines(ModelRun& run, SweepOutput& out, SweepReport& report, const SweepVariant& first);

}  // namespace boxlod
