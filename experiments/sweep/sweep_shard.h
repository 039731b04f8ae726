// A part of a sweep that runs on its own (docs/sweeps.md: Shards).
#pragma once
#include "experiments/sweep/sweep_config.h"

#include <cstddef>
#include <string>
#include <vector>

namespace boxlod {

// A shard of a sweep: one model (its position in `models`, from 0) and one
// level mode, with every box kind, interpolation, level, view, distance and
// render mode; the baselines go with the model's first level mode, whose
// levels they follow. Shards run apart (on a cluster, a job each) and make
// exactly the rows the whole sweep makes for them (docs/sweeps.md: Shards).
struct SweepShard {
    std::size_t model = 0;
    LevelMode level_mode = LevelMode::top_down;
};
std::vector<SweepShard> sweep_shards(const SweepConfig& config);  // model-major
SweepConfig shard_config(const SweepConfig& config, const SweepShard& shard);
// "M:MODE": the model's position from 1 and a level mode of the config. Throws InputError.
SweepShard parse_sweep_shard(const SweepConfig& config, const std::string& text);

}  // namespace boxlod
