#include "data_gen/split.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

namespace {

double fixed_length(const SplitSlot& slot, double extent) {
    if (slot.kind == Size::Kind::absolute) return slot.value;
    return slot.kind == Size::Kind::relative ? slot.value * extent : 0;
}

double floating_length(const SplitSlot& slot) { return slot.kind == Size::Kind::floating ? slot.value : 0; }

}  // namespace

SplitLayout layout_split(const std::vector<SplitSlot>& slots, double extent, std::size_t max_pieces) {
    const double tolerance = 1e-6 * std::max(1.0, extent);
    double outside_fixed = 0, outside_floating = 0, group_fixed = 0, group_floating = 0;
    for (const SplitSlot& slot : slots) {
        (slot.repeated ? group_fixed : outside_fixed) += fixed_length(slot, extent);
        (slot.repeated ? group_floating : outside_floating) += floating_length(slot);
    }
    std::size_t repetitions = 0;
    double group_length = group_fixed + group_floating;
    if (group_length > 0) {
        double room = extent - outside_fixed - outside_floating;
        double count = group_floating > 0 ? std::max(1.0, std::round(room / group_length))
                                          : std::floor(room / group_length + 1e-6);
        std::size_t group_slots =
            std::count_if(slots.begin(), slots.end(), [](const SplitSlot& s) { return s.repeated; });
        count = std::clamp(count, 0.0, double(max_pieces / std::max<std::size_t>(1, group_slots)));
        repetitions = std::size_t(count);
        // The group's absolute parts must fit beside the others.
        while (repetitions > 0 && outside_fixed + repetitions * group_fixed > extent + tolerance)
            --repetitions;
    }

    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < slots.size(); ++i) {
        if (!slots[i].repeated) {
            order.push_back(i);
            continue;
        }
        std::size_t end = i;
        while (end < slots.size() && slots[end].repeated) ++end;
        for (std::size_t r = 0; r < repetitions && order.size() < max_pieces; ++r)
            for (std::size_t k = i; k < end; ++k) order.push_back(k);
        i = end - 1;
    }

    SplitLayout layout;
    double fixed = 0, floating = 0;
    for (std::size_t i : order) {
        fixed += fixed_length(slots[i], extent);
        floating += floating_length(slots[i]);
    }
    layout.needed = fixed;
    if (fixed > extent + tolerance) {
        layout.fits = false;
        return layout;
    }
    double scale = floating > 0 ? std::max(0.0, extent - fixed) / floating : 0;
    double offset = 0;
    for (std::size_t i : order) {
        double size = fixed_length(slots[i], extent) + floating_length(slots[i]) * scale;
        layout.pieces.push_back({i, offset, size});
        offset += size;
    }
    return layout;
}

}  // namespace boxlod
