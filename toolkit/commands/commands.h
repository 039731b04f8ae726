// The toolkit's commands: models in and out, rendering, level values, LoD
// building and the interactive viewer.
#pragma once
#include "base/command_registry.h"

namespace boxlod {

Subcommand info_subcommand();
Subcommand convert_subcommand();
Subcommand render_subcommand();
Subcommand levels_subcommand();
Subcommand build_subcommand();
Subcommand tiles_subcommand();
Subcommand view_subcommand();

// For the commands that write a model (convert, simplify), which merge equal
// materials and drop unused ones (toolkit/model/material_merge.h) unless told not to.
inline Option keep_materials_option() {
    return {"keep-materials", "", "keep every material as read, unused ones and an importer's copies too"};
}

// For the commands that write levels for engines (build --chain, tiles): a
// level is one node per material (toolkit/lod/draw_calls.h) unless told not to.
inline Option keep_hierarchy_option() {
    return {"keep-hierarchy", "",
            "keep one node per kept part and box in each level, with its scope and rule in extras, instead of one node per "
            "material (draw call)"};
}

inline std::vector<Subcommand> toolkit_commands() {
    return {info_subcommand(),   convert_subcommand(), render_subcommand(), levels_subcommand(),
            build_subcommand(),  tiles_subcommand(),   view_subcommand()};
}

}  // namespace boxlod
