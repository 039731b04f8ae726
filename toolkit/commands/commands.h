// The toolkit's commands: models in and out, rendering, level values, LoD
// building and the interactive viewer.
#pragma once
#include "base/command_registry.h"
#include "base/key_values.h"
#include "toolkit/lod/chain/error_by_distance.h"

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
// level is one node per material (toolkit/lod/hybrid/draw_calls.h) unless told not to.
inline Option keep_hierarchy_option() {
    return {"keep-hierarchy", "",
            "keep one node per kept part and box in each level, with its scope and rule in extras, instead "
            "of one node per material"};
}

// For the commands that write chains for engines (build --chain, tiles): the
// error within which a level switches in (toolkit/lod/chain/error_by_distance.h).
constexpr double default_switch_error = 0.05;
inline Option switch_error_option() {
    return {
        "switch-error", "E",
        "each level switches in at the nearest distance beyond which its ꟻLIP against the original, over "
        "the pixels either covers, stays within E (measured from four views in half octaves out to where "
        "the model spans 4 pixels); 0: at its sizing distance, where its texels meet the screen's pixels; "
        "else at least " +
            format_number(switch_error_range.min),
        NumberRange{0, switch_error_range.max}, format_number(default_switch_error)};
}
inline double switch_error(const Arguments& arguments) {
    const double error = arguments.number("switch-error");
    check_switch_error(error, "--switch-error");
    return error;
}

inline std::vector<Subcommand> toolkit_commands() {
    return {info_subcommand(),  convert_subcommand(), render_subcommand(), levels_subcommand(),
            build_subcommand(), tiles_subcommand(),   view_subcommand()};
}

}  // namespace boxlod
