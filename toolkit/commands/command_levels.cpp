#include "base/common_options.h"
#include "base/key_values.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "toolkit/boxlod.h"
#include "toolkit/commands/commands.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/cut/level_values.h"
#include "toolkit/lod/pages/boxes.h"
#include "toolkit/lod/parameter_file.h"

#include <cstdio>

namespace boxlod {

static int run_levels(const Arguments& arguments) {
    if (!arguments.has("level-mode"))
        throw InputError("boxlod levels: --level-mode M is required (see --help)");
    LodParameters parameters;  // the same defaults as `boxlod build`
    apply_lod_options(arguments, parameters);
    const LevelMode mode = parameters.level_mode;
    const BoxKind kind = parameters.box_kind;
    const Interpolation interpolation = parameters.interpolation;
    const int wanted_levels = parameters.wanted_levels;
    const int threads = threads_from(arguments);

    const std::string& path = arguments.positionals[0];
    Model model = read_model(path, parameters.city_lod);
    if (model.is_lod) throw InputError(path + ": an LoD exported by boxlod cannot be simplified again");

    // Only the box modes and error-greedy look at boxes.
    std::vector<std::optional<OrientedBox>> boxes;
    if (uses_boxes(mode)) {
        const auto start = Clock::now();
        MinimalBoxCounts counts;
        boxes = node_boxes(model, kind, threads, counts);
        std::fprintf(
            stderr, "boxes: %.3f s on %d thread(s); minimal boxes for %zu nodes: %zu solved, %zu reused\n",
            seconds_since(start), thread_count(threads), counts.nodes, counts.computed, counts.reused);
    }
    // hybrid's levels are prefixes of a plan that measures its proxies by rendering them (hybrid.h); budgets
    // are fractions of the original's bytes and price boxes at the sizing distance: both need a chain.
    LevelValues values = mode == LevelMode::hybrid || !parameters.budgets.empty()
                             ? Chain(model, parameters, threads, {.boxes = &boxes}).level_values()
                             : compute_level_values(model, mode, wanted_levels, interpolation, boxes);

    KeyValues report{text_entry("model", path), text_entry("level_mode", level_mode_name(mode))};
    if (uses_boxes(mode)) report.push_back(text_entry("box_kind", box_kind_name(kind)));
    if (is_box_mode(mode)) report.push_back(text_entry("interpolation", interpolation_name(interpolation)));
    if (uses_boxes(mode) && parameters.budgets.empty())
        report.push_back(number_entry("wanted_levels", wanted_levels));
    if (!parameters.budgets.empty())
        report.push_back(text_entry("budgets", format_budgets(parameters.budgets)));
    report.push_back(number_entry("obtained_levels", values.obtained_levels));
    report.push_back(number_entry("nodes", double(model.nodes.size())));
    for (std::size_t i = 0; i < values.level.size(); ++i)
        report.push_back(number_entry("level." + std::to_string(i), values.level[i]));
    print_report(report, arguments);
    return 0;
}

Subcommand levels_subcommand() {
    std::vector<Option> options =
        lod_options({"city_lod", "level_mode", "wanted_levels", "budgets", "box_kind", "interpolation"});
    for (Option& option : options)
        if (option.name == "level-mode")
            option.help = enum_names(level_modes(), ", ", " or ") + " (required)";
    return {{"levels", "MODEL",
             "Print every node's level value (level.K = L for node K) and the obtained number of levels.",
             with_options(options, {threads_option("threads for the boxes"), json_option()}), 1, 1},
            run_levels};
}

}  // namespace boxlod
