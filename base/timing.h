// Wall-clock seconds for progress and timing reports; they never enter a file
// that must be byte-identical run to run (docs/design.md: Determinism).
#pragma once
#include <chrono>

namespace boxlod {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Adds the seconds from its making to the end of its scope to `total`:
//   { const ScopedTimer timer(times.bake); bake(...); }
class ScopedTimer {
public:
    explicit ScopedTimer(double& total) : total_(total) {}
    ~ScopedTimer() { total_ += seconds_since(start_); }
    ScopedTimer(const ScopedTimer&) = delete;
    ScopedTimer& operator=(const ScopedTimer&) = delete;

private:
    double& total_;
    const Clock::time_point start_ = Clock::now();
};

// Runs `work`, adding its seconds to `total`, and returns what it returns:
//   Shot shot = timed(report.render_seconds, [&] { return render_shot(...); });
template <typename Work>
auto timed(double& total, Work&& work) {
    const ScopedTimer timer(total);
    return work();
}

}  // namespace boxlod
