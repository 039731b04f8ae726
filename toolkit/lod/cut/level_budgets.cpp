#include "toolkit/lod/cut/level_budgets.h"

#include "base/key_values.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace boxlod {
namespace {

struct ByteUnit {
    const char* name;
    double bytes;
};
constexpr std::array<ByteUnit, 7> byte_units{{{"B", 1},
                                              {"kB", 1e3},
                                              {"MB", 1e6},
                                              {"GB", 1e9},
                                              {"KiB", 1024.0},
                                              {"MiB", 1024.0 * 1024},
                                              {"GiB", 1024.0 * 1024 * 1024}}};
constexpr double max_budget_bytes = 1e15;
constexpr std::size_t max_budgets = 64;  // as wanted_levels' range

// One item: "0.25" or "300kB"; returns what is wrong.
std::string parse_budget(const std::string& item, ByteBudget& budget) {
    double number = 0;
    auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), number);
    if (error != std::errc() || end == item.data() || !std::isfinite(number))
        return "'" + item + "' is neither a fraction nor a size (0.25, 300kB)";
    const std::string unit(end, item.data() + item.size());
    if (unit.empty()) {
        if (!(number > 0 && number <= 1))
            return "the fraction '" + item + "' is outside (0, 1] of the original's bytes";
        budget = {true, number};
        return "";
    }
    for (const ByteUnit& u : byte_units)
        if (unit == u.name) {
            const double bytes = std::round(number * u.bytes);
            if (!(bytes >= 1 && bytes <= max_budget_bytes))
                return "the size '" + item + "' is outside [1 B, 1e15 B]";
            budget = {false, bytes};
            return "";
        }
    return "'" + item + "': unknown unit '" + unit + "' (B, kB, MB, GB, KiB, MiB, GiB)";
}

}  // namespace

std::string parse_budgets(const std::string& text, std::vector<ByteBudget>& budgets) {
    std::vector<ByteBudget> parsed;
    if (text != "none") {
        const std::vector<std::string> items = comma_list(text);
        if (std::find(items.begin(), items.end(), "") != items.end())
            return "'" + text + "' is no list of budgets (0.5,0.25 or 2MB,500kB), or none";
        for (const std::string& item : items) {
            ByteBudget budget;
            if (std::string problem = parse_budget(item, budget); !problem.empty()) return problem;
            if (!parsed.empty() && budget.fraction != parsed.back().fraction)
                return "'" + text + "' mixes fractions and sizes: give all budgets one way";
            if (!parsed.empty() && !(budget.value < parsed.back().value))
                return "'" + item + "' comes after '" + format_budgets({parsed.back()}) +
                       "': budgets must descend, level 1 (the finest) first";
            parsed.push_back(budget);
        }
        if (parsed.size() > max_budgets) return std::to_string(parsed.size()) + " budgets: at most 64 levels";
    }
    budgets = std::move(parsed);
    return "";
}

std::string format_budgets(const std::vector<ByteBudget>& budgets) {
    if (budgets.empty()) return "none";
    std::string text;
    for (const ByteBudget& b : budgets) {
        if (!text.empty()) text += ',';
        text += format_number(b.value);
        if (!b.fraction) text += 'B';
    }
    return text;
}

double budget_bytes(const ByteBudget& budget, double original_bytes) {
    return budget.fraction ? budget.value * original_bytes : budget.value;
}

std::vector<double> geometric_budgets(double start_bytes, double original_bytes, int levels) {
    const double start = std::max(start_bytes, 1.0), original = std::max(original_bytes, 1.0);
    std::vector<double> budgets;
    for (int c = 1; c <= levels; ++c) {
        const double t = double(c) / levels;
        budgets.push_back(std::exp((1 - t) * std::log(original) + t * std::log(start)));
    }
    return budgets;
}

std::size_t longest_prefix_within(const std::vector<double>& bytes, double budget) {
    std::size_t steps = 0;
    for (std::size_t k = 0; k < bytes.size(); ++k)
        if (bytes[k] <= budget * (1 + 1e-12)) steps = k;
    return steps;
}

std::size_t best_prefix_within(const std::vector<double>& bytes, const std::vector<double>& error,
                               double budget) {
    // Not the longest prefix: an opening that gains nothing yet can raise the
    // error for a while. Where the start is over the budget, any prefix within it beats it.
    auto fits = [&](std::size_t k) { return bytes[k] <= budget * (1 + 1e-12); };
    std::size_t steps = 0;
    for (std::size_t k = 1; k < bytes.size(); ++k)
        if (fits(k) && (error[k] < error[steps] || !fits(steps))) steps = k;
    return steps;
}

}  // namespace boxlod
