// `boxlod sweep`: the cross product of a SweepConfig — models x level modes x
// box kinds x interpolations x levels x views x distances x render modes —
// each LoD compared with the original by every metric.
//
// OUTDIR/results.csv holds one row per combination, in that order, with the
// LoD's counts and the metrics; it is byte-identical for any thread count.
// OUTDIR/timings.csv holds the seconds under the same key columns (timings
// differ from run to run, so they live apart). Resumable: rows already in
// results.csv are not computed again; both files are rewritten atomically
// after every finished LoD, so an interrupted sweep keeps what it has.
#pragma once
#include "experiments/sweep/sweep_config.h"
#include "experiments/sweep/sweep_report.h"
#include "experiments/sweep/sweep_shard.h"

#include <cstdio>
#include <string>
#include <vector>

namespace boxlod {

// The columns of results.csv and of timings.csv for a config's metrics.
std::vector<std::string> result_columns(const SweepConfig& config);
std::vector<std::string> timing_columns();

// `threads` overrides the config's when >= 0. Progress lines (with an ETA) go
// to `progress` when not null. Throws InputError for bad models or a
// results.csv whose columns differ from this config's.
SweepReport run_sweep(const SweepConfig& config, const std::string& output_folder, int threads = -1,
                      std::FILE* progress = nullptr);

// The whole sweep from its shards' output folders: their rows are read into
// OUTDIR's tables and the sweep runs there, computing only rows no shard
// has; results.csv gets the bytes the unsharded sweep writes. Throws
// InputError when two shards disagree on a row or a table has other columns.
SweepReport merge_sweep(const SweepConfig& config, const std::vector<std::string>& shard_folders,
                        const std::string& output_folder, int threads = -1, std::FILE* progress = nullptr);

}  // namespace boxlod
