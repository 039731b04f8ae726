// data_gen's command: deriving grammars, samples and cities into models.
#pragma once
#include "base/command_registry.h"

namespace boxlod {

Subcommand generate_subcommand();

inline std::vector<Subcommand> data_gen_commands() { return {generate_subcommand()}; }

}  // namespace boxlod
