#include "experiments/sweep/sweep_shard.h"

#include "base/input_error.h"
#include "base/number_text.h"
#include "toolkit/lod/cut/level_modes.h"

#include <algorithm>

namespace boxlod {

std::vector<SweepShard> sweep_shards(const SweepConfig& config) {
    std::vector<SweepShard> shards;
    for (std::size_t m = 0; m < config.models.size(); ++m)
        for (LevelMode mode : config.level_modes) shards.push_back({m, mode});
    return shards;
}

SweepConfig shard_config(const SweepConfig& config, const SweepShard& shard) {
    SweepConfig part = config;
    part.models = {config.models.at(shard.model)};
    part.level_modes = {shard.level_mode};
    if (shard.level_mode != config.level_modes.front()) part.baselines.clear();
    return part;
}

SweepShard parse_sweep_shard(const SweepConfig& config, const std::string& text) {
    const std::size_t colon = text.find(':');
    auto fail = [&](const std::string& what) {
        throw InputError("boxlod sweep: --shard '" + text + "': " + what);
    };
    if (colon == std::string::npos)
        fail("expected M:MODE, the model's position from 1 and a level mode of the config");
    const std::string position = text.substr(0, colon), mode_name = text.substr(colon + 1);
    const NumberRange models{1, double(config.models.size())};
    const std::optional<std::size_t> m = number_within<std::size_t>(position, models);  // whole, decimal
    if (!m) fail(out_of_range_message(models, position));
    SweepShard shard{*m - 1, LevelMode::top_down};
    if (!parse_level_mode(mode_name, shard.level_mode) ||
        std::find(config.level_modes.begin(), config.level_modes.end(), shard.level_mode) ==
            config.level_modes.end())
        fail("'" + mode_name + "' is not one of the config's level modes");
    return shard;
}

}  // namespace boxlod
