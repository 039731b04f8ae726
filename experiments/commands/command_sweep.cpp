#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/input_error.h"
#include "base/key_values.h"
#include "base/parallel.h"
#include "experiments/commands/commands.h"
#include "experiments/sweep/sweep.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace boxlod {
namespace {

// The folders under `parent` that hold a results.csv, by name.
std::vector<std::string> shard_folders(const std::string& parent) {
    std::error_code error;
    std::vector<std::string> folders;
    for (const auto& entry : std::filesystem::directory_iterator(parent, error)) {
        const std::filesystem::path results = entry.path() / "results.csv";
        std::error_code ignored;
        if (std::filesystem::is_regular_file(results, ignored))
            folders.push_back(entry.path().string());
        else if (std::filesystem::exists(results,
                                         ignored))  // a shard whose rows cannot be read is no shard to skip
            throw_input_error(results.string(), "", "is not a file: the shard's rows cannot be merged");
    }
    if (error) throw_input_error(parent, "", "cannot read the shards' folder: " + error.message());
    if (folders.empty()) throw_input_error(parent, "", "no shard folder with a results.csv in it");
    std::sort(folders.begin(), folders.end());
    return folders;
}

int run_sweep_command(const Arguments& arguments) {
    if (!arguments.has("output")) throw InputError("boxlod sweep: -o/--output OUTDIR is required");
    check_output_directory(arguments.text("output"));
    int threads = threads_from(arguments, -1);  // -1: the config's
    SweepConfig config = load_sweep_config(arguments.positionals[0]);
    const std::string& output = arguments.text("output");
    if (arguments.has("shard") && arguments.has("merge"))
        throw InputError("boxlod sweep: --shard and --merge exclude each other");
    if (arguments.has("shard"))
        config = shard_config(config, parse_sweep_shard(config, arguments.text("shard")));
    std::vector<std::string> shards;
    if (arguments.has("merge")) shards = shard_folders(arguments.text("merge"));
    SweepReport r = merge_sweep(config, shards, output, threads, stderr);
    KeyValues report{text_entry("results", (std::filesystem::path(output) / "results.csv").string()),
                     text_entry("timings", (std::filesystem::path(output) / "timings.csv").string()),
                     number_entry("rows", double(r.rows)),
                     number_entry("rows_computed", double(r.rows_computed)),
                     number_entry("rows_skipped", double(r.rows_skipped)),
                     number_entry("lods_built", double(r.lods_built)),
                     number_entry("lod_renders", double(r.lod_renders)),
                     number_entry("original_renders", double(r.original_renders)),
                     number_entry("boxes_seconds", r.boxes_seconds),
                     number_entry("build_seconds", r.build_seconds),
                     number_entry("render_seconds", r.render_seconds),
                     number_entry("metric_seconds", r.metric_seconds),
                     number_entry("seconds", r.total_seconds)};
    print_report(report, arguments);
    return 0;
}

}  // namespace

Subcommand sweep_subcommand() {
    std::string keys;
    for (const std::string& key : sweep_config_keys()) keys += (keys.empty() ? "" : ", ") + key;
    return {{"sweep",
             "CONFIG",
             "Run a sweep: every model x level mode x box kind x interpolation x level x view x distance x "
             "render mode of CONFIG (key = value lines: " +
                 keys +
                 "), each LoD compared with the original. Writes OUTDIR/results.csv (identical for any "
                 "thread count), OUTDIR/timings.csv and, if asked, OUTDIR/images/; rows already in "
                 "results.csv are skipped.",
             {{"output", "OUTDIR", "folder for results.csv, timings.csv and images/ (required)", {}, "", 'o'},
              threads_option("threads to use, 0 = all cores", "the config's threads"),
              {"shard", "M:MODE",
               "only model M (from 1) with level mode MODE, and the baselines if MODE is the config's first: "
               "a part of the sweep that runs on its own (docs/sweeps.md: Shards)"},
              {"merge", "SHARDS",
               "start from the rows of the shards' output folders under SHARDS; OUTDIR/results.csv gets the "
               "bytes of the whole sweep's"},
              json_option()},
             1,
             1},
            run_sweep_command};
}

}  // namespace boxlod
