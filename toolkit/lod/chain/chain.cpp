#include "toolkit/lod/chain/chain.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "toolkit/lod/lod_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace boxlod {

double doubled_distance(double level_one_distance, int level) {
    return std::min(level_one_distance * std::ldexp(1.0, level - 1), parameter_range::distance.max);
}

std::vector<float> level_distances(const LevelDistances& rule, float distance, int levels,
                                   const std::vector<ByteBudget>& budgets) {
    std::vector<float> distances;
    switch (rule.rule) {
    case LevelDistances::Rule::same: break;
    case LevelDistances::Rule::doubling:
        for (int c = 1; c <= levels; ++c) {
            double sized = doubled_distance(distance, c);
            // A budget's level is never needed farther than where a level-1 rendering's bytes,
            // falling at least as 1/d (a mesh's), come down to it; halvings and the README's
            // ladder (0.5, 0.25, 0.1, 0.05, ...) stay doubled. Levels without budgets (geometric
            // ones, derived later) keep the doubling.
            if (int(budgets.size()) == levels)
                sized = std::min(sized, distance * budgets.front().value / budgets[std::size_t(c - 1)].value);
            distances.push_back(float(sized));
        }
        break;
    case LevelDistances::Rule::listed:
        if (int(rule.listed.size()) != levels) {
            // Known only now, with the levels: named as the parameter file and the option name it.
            std::string listed;
            for (float d : rule.listed) listed.append(listed.empty() ? "" : ",").append(format_number(d));
            throw InputError("level_distances (--level-distances) " + listed + ": " +
                             std::to_string(rule.listed.size()) + " distances for " + std::to_string(levels) +
                             " levels; list " + std::to_string(levels) + " (levels 1.." +
                             std::to_string(levels) + "), or auto, or same");
        }
        distances = rule.listed;
    }
    return distances;
}

Chain::Chain(const Model& model, const LodParameters& parameters, int threads, const ChainOptions& options)
    : model(model),
      threads(threads),
      measurements(parameters.level_mode == LevelMode::hybrid ? make_hybrid_measurements(model) : nullptr),
      first(start_lod(model, parameters, threads, options.boxes, measurements.get())),
      distances(level_distances(parameters.level_distances, first->input.parameters.distance,
                                obtained_levels(), parameters.budgets)) {
    first->input.budgets_strict = options.budgets_strict;
}

Chain::~Chain() = default;

const LodParameters& Chain::parameters() const { return first->input.parameters; }

int Chain::obtained_levels() const { return first->derived.levels.obtained_levels; }

const LevelValues& Chain::level_values() const { return first->derived.levels; }

const std::vector<std::optional<OrientedBox>>& Chain::boxes() const { return first->derived.boxes; }

LodSession& Chain::for_level(int level) {
    // A level sized for the first's distance (auto's level 1) is the first's: its boxes baked and its plan
    // made once. Past the levels obtained: build_lod refuses it.
    if (level <= 0 || level > int(distances.size()) ||
        distances[std::size_t(level - 1)] == first->input.parameters.distance)
        return *first;
    std::unique_ptr<LodSession>& session = sized[distances[std::size_t(level - 1)]];
    if (!session) {
        LodParameters p = first->input.parameters;
        p.distance = distances[std::size_t(level - 1)];
        p.level_distances.rule = LevelDistances::Rule::same;  // the session sizes for this one distance
        session = start_lod(model, p, threads, &first->derived.boxes, measurements.get());
        session->input.budgets_strict = first->input.budgets_strict;
    }
    return *session;
}

const LodParameters& Chain::sized_parameters(int level) { return for_level(level).input.parameters; }

const TextureSizing& Chain::sizing(int level) { return for_level(level).derived.sizing; }

Lod Chain::build(int level) { return build_lod(for_level(level), level, threads); }

Lod Chain::build_baked_model(const std::vector<Primitive>& geometry, int texel_scale, int level) {
    return boxlod::build_baked_model(for_level(level), geometry, texel_scale, level, threads);
}

LodTimes Chain::times() const {
    LodTimes t = first->times;
    t.preview += written.preview;
    t.write += written.write;
    for (const auto& [distance, session] : sized) {
        t.levels += session->times.levels;  // each distance plans its own levels (hybrid measures again)
        t.bake += session->times.bake;
        t.pack += session->times.pack;
        t.mesh += session->times.mesh;
        t.preview += session->times.preview;
        t.write += session->times.write;
    }
    return t;
}

void check_chain_budgets(Chain& chain, const std::vector<int>& levels) {
    for (int level : levels) check_budget_reachable(chain.for_level(level), level, chain.threads);
}

int take_distinct_levels(Chain& chain, int first, int last, int max_levels,
                         const std::function<void(ChainLevel)>& take) {
    std::optional<ChainLevel>
        pending;  // the last distinct level, held until the next one shows it has no more repeats
    int held = 0, level = first;
    for (; level <= last; ++level) {
        Lod lod = chain.build(level);
        if (pending && draws_the_same(pending->lod.model, lod.model)) {
            pending->same_levels.push_back(level);
            continue;
        }
        if (held == max_levels) break;
        if (pending) take(std::move(*pending));
        pending = ChainLevel{level, std::move(lod), {}};
        ++held;
    }
    if (pending) take(std::move(*pending));
    return level;
}

SwitchedChain switched_levels(Chain& chain, double threshold, int max_levels) {
    std::vector<ChainLevel> distinct;
    take_distinct_levels(chain, 0, chain.obtained_levels(), std::numeric_limits<int>::max(),
                         [&](ChainLevel level) { distinct.push_back(std::move(level)); });
    SwitchedChain switched;
    ErrorByDistance measured;
    std::vector<double> switches;
    std::vector<std::uint64_t> bytes;
    for (const ChainLevel& level : distinct) bytes.push_back(combined_cost({&level.lod.cost}).bytes());
    if (threshold > 0) {
        std::vector<const Model*> models;
        for (const ChainLevel& level : distinct) models.push_back(&level.lod.model);
        const LodParameters& p = chain.parameters();
        measured = measure_error_by_distance(chain.model, models, chain.sizing(0), p, chain.threads);
        switches = switch_distances(measured, threshold);
        switched.distances = measured.distances;
    } else {
        // Where its texels meet the screen's pixels: d_c, or where auto distances put it when every
        // level is sized for one distance (--manual), which would otherwise switch all at once.
        const LodParameters& p = chain.parameters();
        const std::vector<float> automatic =
            level_distances({}, p.distance, chain.obtained_levels(), p.budgets);
        for (const ChainLevel& level : distinct)
            switches.push_back(!chain.distances.empty() ? chain.sized_parameters(level.level).distance
                               : level.level == 0       ? doubled_distance(p.distance, 0)
                                                        : automatic[std::size_t(level.level - 1)]);
    }
    const std::vector<std::size_t> reachable = reachable_levels(switches, bytes);
    switched.distinct = int(distinct.size());
    switched.reachable = int(reachable.size());
    for (std::size_t k : reachable) {
        if (int(switched.levels.size()) == max_levels) break;
        switched.switch_distances.push_back(k == 0 ? 0 : switches[k]);
        if (threshold > 0) switched.errors.push_back(measured.errors[k]);
        switched.levels.push_back(std::move(distinct[k]));
    }
    return switched;
}

}  // namespace boxlod
