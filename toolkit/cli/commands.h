// The `boxlod` subcommands. Each declares its options and runs with parsed
// arguments; stdout gets `key = value` lines, stderr progress and messages.
#pragma once
#include "renderer/input_error.h"
#include "toolkit/cli/options.h"

#include <vector>

namespace boxlod {

struct Subcommand {
    Command command;
    int (*run)(const Arguments&);
};

Subcommand info_subcommand();
Subcommand convert_subcommand();
Subcommand render_subcommand();
Subcommand generate_subcommand();
Subcommand levels_subcommand();
Subcommand build_subcommand();
Subcommand view_subcommand();
Subcommand compare_subcommand();
Subcommand sweep_subcommand();
Subcommand simplify_subcommand();
Subcommand city_subcommand();

}  // namespace boxlod
