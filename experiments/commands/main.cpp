// boxlod: textured-box level of detail for hierarchical architecture. The
// program is every layer's commands, so it is linked here, at the top.
#include "base/atomic_write.h"
#include "base/freed_memory.h"
#include "data_gen/commands/commands.h"
#include "experiments/commands/commands.h"
#include "toolkit/commands/commands.h"

int main(int argc, char** argv) {
    boxlod::remove_partial_outputs_on_interrupt();  // first, before any thread starts
    boxlod::keep_freed_memory();
    std::vector<boxlod::Subcommand> subcommands = boxlod::toolkit_commands();
    for (auto* layer : {boxlod::data_gen_commands, boxlod::experiments_commands})
        for (boxlod::Subcommand& s : layer()) subcommands.push_back(std::move(s));
    return boxlod::run_subcommands(subcommands, argc, argv);
}
