// Packed drawables unpacked on demand and kept under a memory budget, as an
// engine streams its levels (docs/city.md: Memory). What a frame draws is
// always unpacked; between frames the least recently drawn go first once the
// unpacked ones exceed the budget. What is drawn never depends on the budget,
// only how often a level is unpacked again.
#pragma once
#include "toolkit/drawing/packed_drawable.h"

#include <map>

namespace boxlod {

class ResidentDrawables {
public:
    explicit ResidentDrawables(std::size_t budget_bytes) : budget_(budget_bytes) {}

    // The drawables of `wanted`, in order, unpacked where they are not (in parallel, `threads`
    // as parallel_for's); valid until the next call. Which ones stay unpacked afterwards depends
    // only on the sequence of calls, never on `threads`.
    std::vector<const Drawable*> acquire(const std::vector<const PackedDrawable*>& wanted, int threads);

    struct Counts {
        std::size_t unpacked = 0, evicted = 0;           // over all calls
        std::size_t resident_bytes = 0, peak_bytes = 0;  // PackedDrawable::unpacked_size summed
        double unpack_seconds = 0;
    };
    const Counts& counts() const { return counts_; }

private:
    struct Entry {
        std::unique_ptr<DrawableModel> model;
        std::uint64_t last_used = 0;  // a call and position stamp: unique, so eviction order is fixed
    };
    std::size_t budget_;
    std::uint64_t clock_ = 0;
    std::map<const PackedDrawable*, Entry> entries_;
    Counts counts_;
};

}  // namespace boxlod
