// Wall-clock seconds for progress and timing reports; they never enter a file
// that must be byte-identical run to run (docs/design.md: Determinism).
#pragma once
#include <chrono>

namespace boxlod {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace boxlod
