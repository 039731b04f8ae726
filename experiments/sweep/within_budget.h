// A baseline's level within a byte budget (docs/sweeps.md: levels by byte
// budget are compared at equal bytes): the finest of a family made for a
// triangle target, from a first target down in proportion to the overshoot
// (a few rounds: bytes follow the triangles closely).
#pragma once
#include <algorithm>
#include <cstddef>
#include <functional>

namespace boxlod {

template <class Level>
Level finest_within(std::size_t first_target, double budget, const std::function<Level(std::size_t)>& make,
                    const std::function<double(const Level&)>& bytes_of) {
    std::size_t target = std::max<std::size_t>(first_target, 1);
    Level level = make(target);
    for (int round = 0; round < 16; ++round) {
        const double bytes = bytes_of(level);
        if (bytes <= budget || target == 1) break;
        target = std::max<std::size_t>(
            1, std::min(target - 1, std::size_t(double(target) * budget / bytes * 0.98)));
        level = make(target);
    }
    return level;
}

}  // namespace boxlod
