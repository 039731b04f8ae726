// The experiments' commands: image metrics, the simplification baseline,
// sweeps and city fly-throughs.
#pragma once
#include "base/command_registry.h"

namespace boxlod {

Subcommand compare_subcommand();
Subcommand simplify_subcommand();
Subcommand sweep_subcommand();
Subcommand city_subcommand();

inline std::vector<Subcommand> experiments_commands() {
    return {compare_subcommand(), simplify_subcommand(), sweep_subcommand(), city_subcommand()};
}

}  // namespace boxlod
