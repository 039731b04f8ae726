// data_gen's command: deriving grammars, samples and cities into models.
#pragma once
#include "base/command_registry.h"

namespace boxlod {

Subcommand generate_subcommand();

// --designs K, which `generate --city` and `city` share: the distinct
// building designs a city's lots draw from (data_gen/city.h).
Option designs_option();

inline std::vector<Subcommand> data_gen_commands() { return {generate_subcommand()}; }

}  // namespace boxlod
