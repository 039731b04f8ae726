// Levels by byte budget (beyond the manual; docs/design.md: Levels by byte
// budget). `--budgets 0.5,0.25,0.1,0.05` makes one level per budget, level c
// the best cut within the c-th: a fraction of the original's bytes, or a size
// ("2MB", "300kB", "65536B"). The modes that order their cuts by bytes
// (error-greedy and hybrid) take the best prefix of their order whose
// estimated bytes fit; the builder then checks the level's real bytes (mesh +
// every texture, GPU-compressed: cost.h) and steps back until they fit too.
#pragma once
#include <string>
#include <vector>

namespace boxlod {

struct ByteBudget {
    bool fraction = true;  // of the original's bytes, in (0, 1]; false: `value` bytes
    double value = 0;
};

// "none" or a comma-separated list, descending, all fractions or all sizes
// (B, kB, MB, GB in powers of 1000; KiB, MiB, GiB in powers of 1024), at most
// 64. Returns what is wrong ("" when nothing is).
std::string parse_budgets(const std::string& text, std::vector<ByteBudget>& budgets);
std::string format_budgets(const std::vector<ByteBudget>& budgets);  // reads back exactly

double budget_bytes(const ByteBudget& budget, double original_bytes);

// B_1..B_N spaced geometrically from the original's bytes to the coarsest
// cut's, B_c = B_orig^(1 - c/N) B_start^(c/N): the levels' budgets when none
// are given (error-greedy's and hybrid's default).
std::vector<double> geometric_budgets(double start_bytes, double original_bytes, int levels);

// Prefixes of an order of cuts (bytes[k], error[k] after k steps) within a budget:
// the longest, or the one of lowest error (the shortest of equal error, and any
// within the budget before a start beyond it); 0 when none fits.
std::size_t longest_prefix_within(const std::vector<double>& bytes, double budget);
std::size_t best_prefix_within(const std::vector<double>& bytes, const std::vector<double>& error,
                               double budget);

}  // namespace boxlod
