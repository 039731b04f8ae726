#include "toolkit/drawing/resident_drawables.h"

#include "base/parallel.h"
#include "base/timing.h"

#include <algorithm>

namespace boxlod {

std::vector<const Drawable*> ResidentDrawables::acquire(const std::vector<const PackedDrawable*>& wanted,
                                                        int threads) {
    std::vector<const PackedDrawable*> missing;
    for (const PackedDrawable* packed : wanted) {
        auto [entry, added] = entries_.try_emplace(packed);
        entry->second.last_used = ++clock_;
        if (added) missing.push_back(packed);
    }
    {
        const ScopedTimer timer(counts_.unpack_seconds);
        std::vector<std::unique_ptr<DrawableModel>> unpacked(missing.size());
        parallel_for(missing.size(), threads,
                     [&](std::size_t i) { unpacked[i] = unpack_drawable(*missing[i]); });
        for (std::size_t i = 0; i < missing.size(); ++i) {
            entries_[missing[i]].model = std::move(unpacked[i]);
            counts_.resident_bytes += missing[i]->unpacked_size;
        }
    }
    counts_.unpacked += missing.size();
    counts_.peak_bytes = std::max(counts_.peak_bytes, counts_.resident_bytes);

    // Over budget: evict the least recently used of those this call does not draw.
    const std::uint64_t this_call = clock_ - wanted.size();
    std::vector<std::pair<std::uint64_t, const PackedDrawable*>> older;
    for (const auto& [packed, entry] : entries_)
        if (entry.last_used <= this_call) older.emplace_back(entry.last_used, packed);
    std::sort(older.begin(), older.end());
    for (auto [stamp, packed] : older) {
        if (counts_.resident_bytes <= budget_) break;
        counts_.resident_bytes -= packed->unpacked_size;
        entries_.erase(packed);
        ++counts_.evicted;
    }

    std::vector<const Drawable*> drawables;
    for (const PackedDrawable* packed : wanted) drawables.push_back(&entries_.at(packed).model->drawable);
    return drawables;
}

}  // namespace boxlod
