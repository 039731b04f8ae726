// Deterministic parallel loops: work items are claimed dynamically, but each
// item writes only its own output, so results never depend on scheduling.
#pragma once
#include "base/input_error.h"

#include <cstddef>
#include <functional>

namespace boxlod {

// The thread counts a user may ask for; 0 means all cores.
constexpr NumberRange thread_count_range{0, 1024};

// Number of threads to use when the user asked for `requested` (0 = all cores).
int thread_count(int requested);

// Calls body(item) for item in [0, count) on up to `threads` threads.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t item)>& body);

}  // namespace boxlod
