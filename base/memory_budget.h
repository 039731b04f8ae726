// Memory budgets (docs/design.md: Errors): a request whose estimated need
// exceeds the budget is refused before its memory is allocated, with one line
// saying what it would need, instead of running until the machine runs out.
// Every command takes --max-memory GB; by default the budget is half of the
// memory this process may use (the machine's, or less: its cgroup's limit,
// its address-space limit), leaving the rest to the system and to other runs.
#pragma once
#include "base/command_line.h"

#include <string>

namespace boxlod {

constexpr NumberRange max_memory_range{0.001, 1048576};  // GB
Option max_memory_option();

// min(physical memory, cgroup v2 memory.max, RLIMIT_AS), bytes; the default budget is half of it.
double usable_memory();
double default_memory_budget();

// The process's budget, bytes: default_memory_budget() until set (run_subcommands sets it from
// --max-memory), and never more than usable_memory().
double memory_budget();
void set_memory_budget(double bytes);

// "12.5 GB" (decimal units, three significant digits).
std::string memory_text(double bytes);

// Memory that something long-lived holds while it lives (an LoD session's baked
// faces, a level's pages): every check counts it beside the request, so a
// chain of levels is estimated whole, not one level at a time.
class MemoryHold {
public:
    explicit MemoryHold(double bytes = 0);
    ~MemoryHold();
    MemoryHold(MemoryHold&& other) noexcept;
    MemoryHold& operator=(MemoryHold&& other) noexcept;
    void set(double bytes);  // what it holds now

private:
    double bytes_ = 0;
};
double held_memory();  // the sum over every MemoryHold alive

// Throws InputError "WHAT would need N GB, more than the memory budget of M GB
// (--max-memory)" when `bytes` and held_memory() together exceed the budget.
void check_memory(const std::string& what, double bytes);

}  // namespace boxlod
