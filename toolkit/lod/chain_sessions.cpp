#include "toolkit/lod/chain_sessions.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "toolkit/lod/parameter_file.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

std::vector<float> level_distances(const std::string& text, float distance, int levels) {
    std::vector<float> distances;
    if (text == "auto") {
        for (int c = 1; c <= levels; ++c)  // within the range a parameter file reads back (64 levels double past it)
            distances.push_back(float(std::min(double(distance) * std::ldexp(1.0, c - 1), parameter_range::distance.max)));
        return distances;
    }
    for (const std::string& item : comma_list(text)) {
        char* end = nullptr;
        const double d = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !parameter_range::distance.contains(d) || d < parameter_range::min_positive_distance)
            throw InputError("--level-distances: '" + item + "' is not a distance in [" + format_number(parameter_range::min_positive_distance) +
                             ", " + format_number(parameter_range::distance.max) + "] m");
        if (!distances.empty() && float(d) < distances.back())
            throw InputError("--level-distances: " + item + " comes after " + format_number(distances.back()) +
                             ": the distances must ascend, one per level 1.." + std::to_string(levels));
        distances.push_back(float(d));
    }
    if (int(distances.size()) != levels)
        throw InputError("--level-distances: " + std::to_string(distances.size()) + " distances for " +
                         std::to_string(levels) + " levels (1.." + std::to_string(levels) + "), or auto");
    return distances;
}

ChainSessions::ChainSessions(const Model& model, const LodParameters& parameters, int threads)
    : model(model), threads(threads),
      measurements(parameters.level_mode == LevelMode::hybrid ? make_hybrid_measurements(model) : nullptr),
      first(start_lod(model, parameters, threads, nullptr, measurements.get())) {}

LodSession& ChainSessions::for_level(int level) {
    // A level sized for the first's distance (auto's level 1) is the first's: its boxes baked and its plan made once.
    if (distances.empty() || level == 0 || distances[std::size_t(level - 1)] == first->input.parameters.distance) return *first;
    std::unique_ptr<LodSession>& session = sized[distances[std::size_t(level - 1)]];
    if (!session) {
        LodParameters p = first->input.parameters;
        p.distance = distances[std::size_t(level - 1)];
        session = start_lod(model, p, threads, &first->derived.boxes, measurements.get());
    }
    return *session;
}

LodTimes ChainSessions::times() const {
    LodTimes t = first->times;
    for (const auto& [distance, session] : sized) {
        t.levels += session->times.levels;  // each distance plans its own levels (hybrid measures again)
        t.bake += session->times.bake, t.pack += session->times.pack;
        t.mesh += session->times.mesh, t.write += session->times.write;
    }
    return t;
}

}  // namespace boxlod
