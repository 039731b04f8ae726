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

// Half of min(physical memory, cgroup v2 memory.max, RLIMIT_AS), bytes.
double default_memory_budget();

// The process's budget, bytes: default_memory_budget() until set (run_subcommands sets it from --max-memory).
double memory_budget();
void set_memory_budget(double bytes);

// "12.5 GB" (decimal units, three significant digits).
std::string memory_text(double bytes);

// Throws InputError "WHAT would need N GB, more than the memory budget of M GB (--max-memory)".
void check_memory(const std::string& what, double bytes);

}  // namespace boxlod
