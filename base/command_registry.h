// The boxlod program is a list of subcommands: each layer brings its own
// (toolkit/commands, data_gen/commands, experiments/commands), and main()
// hands them all to run_subcommands. Each declares its options and runs with
// parsed arguments; stdout gets `key = value` lines, stderr progress and
// messages (docs/design.md: Errors for the exit status).
#pragma once
#include "base/command_line.h"

#include <vector>

namespace boxlod {

struct Subcommand {
    Command command;
    int (*run)(const Arguments&);
};

// Parses argv, runs the subcommand it names (or prints the overview or its
// --help) and returns the exit status: 2 for bad input or usage (one line on
// stderr), 1 for an internal failure.
int run_subcommands(const std::vector<Subcommand>& subcommands, int argc, char** argv);

}  // namespace boxlod
