#pragma once
// What a sweep did: rows of its cross product, computed and found, and its seconds.

#include <cstddef>

namespace boxlod {

struct SweepReport {
    std::size_t rows = 0;           // rows of the cross product
    std::size_t rows_computed = 0;  // rows computed by this run
    std::size_t rows_skipped = 0;   // rows found in results.csv
    std::size_t lods_built = 0, lod_renders = 0, original_renders = 0;
    double boxes_seconds = 0, build_seconds = 0, render_seconds = 0, metric_seconds = 0, total_seconds = 0;
};

}  // namespace boxlod
