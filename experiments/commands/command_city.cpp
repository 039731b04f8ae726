#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/distinct_files.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "base/parallel.h"
#include "data_gen/city.h"
#include "data_gen/commands/commands.h"
#include "experiments/city/camera_path.h"
#include "experiments/city/fly_through.h"
#include "experiments/commands/commands.h"
#include "toolkit/boxlod.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/selection/strategy_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace boxlod {
namespace {

// The LoD parameters a city takes from the command line (the sizing ones are set per level).
const std::vector<std::string> city_lod_parameters{"city_lod", "level_mode", "wanted_levels",
                                                   "keep_small_subtrees", "keep_cheaper_subtrees"};

const std::string prefix = "boxlod city: ";

constexpr NumberRange detail_range{1e-3, 1e3};

void require(bool ok, const std::string& what) {
    if (!ok) throw InputError(prefix + what);
}

FlyThroughOptions fly_through_options(const Arguments& arguments) {
    FlyThroughOptions options;
    options.strategy = parse_strategy(arguments.text("strategy"), "--strategy");
    options.width = arguments.integer("width");
    options.height = arguments.integer("height");
    options.fovy = float(arguments.number("fovy"));
    options.hysteresis = arguments.number("hysteresis");
    if (arguments.has("budget")) {
        double budget = arguments.number("budget", 0);
        require(budget == std::floor(budget), "--budget takes a whole number of faces");
        options.face_budget = std::size_t(budget);
    }
    options.error_every = arguments.integer("error-every");
    options.pixels_per_degree = arguments.number("ppd");
    apply_lod_options(arguments, options.levels, city_lod_parameters);
    options.base_distance = float(arguments.number("base-distance"));
    options.memory_budget = std::size_t(arguments.integer("memory")) << 20;
    options.threads = threads_from(arguments);
    require(options.threads >= 0, "--threads: expected 0 (all cores) or a positive count");
    return options;
}

// --detail K[,K...]: at most 64 distinct numbers in the detail range (each a pass over every frame).
std::vector<double> details_option(const Arguments& arguments) {
    constexpr std::size_t most_details = 64;
    std::vector<double> details;
    const std::vector<std::string> items = comma_list(arguments.text("detail", "1"));
    require(items.size() <= most_details,
            "--detail takes at most 64 values, got " + std::to_string(items.size()));
    for (const std::string& item : items) {
        char* end = nullptr;
        double detail = std::strtod(item.c_str(), &end);
        require(!item.empty() && end == item.c_str() + item.size() && detail_range.contains(detail) &&
                    std::find(details.begin(), details.end(), detail) == details.end(),
                "--detail takes distinct numbers in [0.001, 1000] separated by commas, got '" +
                    arguments.text("detail") + "'");
        details.push_back(detail);
    }
    require(!details.empty(), "--detail takes distinct positive numbers separated by commas");
    return details;
}

// stdout: the run, then each pass's figures (under detail_<K>. when there are several).
KeyValues city_report(const std::vector<FlyThroughReport>& runs, const FlyThroughOptions& options,
                      const std::string& output, const std::string& path_name) {
    namespace fs = std::filesystem;
    KeyValues report{text_entry("output", output),
                     text_entry("frames_csv", (fs::path(output) / "frames.csv").string()),
                     text_entry("strategy", format_strategy(options.strategy)),
                     text_entry("path", path_name),
                     number_entry("frames", double(runs.front().frames)),
                     number_entry("buildings", double(runs.front().buildings)),
                     number_entry("lods_built", double(runs.front().lods_built)),
                     number_entry("max_level", double(runs.front().level_totals.size() - 1)),
                     number_entry("build_seconds", runs.front().build_seconds),
                     number_entry("levels_packed_bytes", double(runs.front().packed_bytes)),
                     number_entry("levels_unpacked_bytes", double(runs.front().unpacked_bytes))};
    for (const FlyThroughReport& r : runs) {
        std::string key = runs.size() == 1 ? "" : "detail_" + format_number(r.detail) + ".";
        report.push_back(number_entry(key + "detail", r.detail));
        report.push_back(number_entry(key + "faces_mean", r.faces_mean));
        report.push_back(number_entry(key + "faces_min", double(r.faces_min)));
        report.push_back(number_entry(key + "faces_max", double(r.faces_max)));
        for (std::size_t c = 0; c < r.level_totals.size(); ++c)
            report.push_back(
                number_entry(key + "level_" + std::to_string(c) + "_total", double(r.level_totals[c])));
        report.push_back(number_entry(key + "levels_changed", double(r.levels_changed)));
        report.push_back(number_entry(key + "sampled_frames", double(r.sampled_frames)));
        if (r.sampled_frames) {
            report.push_back(number_entry(key + "psnr_mean", r.psnr_mean));
            report.push_back(number_entry(key + "ssim_mean", r.ssim_mean));
            report.push_back(number_entry(key + "flip_mean", r.flip_mean));
        }
        report.push_back(number_entry(key + "select_seconds", r.select_seconds));
        report.push_back(number_entry(key + "select_ms_per_frame",
                                      r.frames ? 1000 * r.select_seconds / double(r.frames) : 0));
        report.push_back(number_entry(key + "levels_unpacked", double(r.levels_unpacked)));
        report.push_back(number_entry(key + "unpack_seconds", r.unpack_seconds));
        report.push_back(number_entry(key + "resident_peak_bytes", double(r.resident_peak_bytes)));
        report.push_back(number_entry(key + "render_seconds", r.render_seconds));
        report.push_back(number_entry(key + "render_ms_per_frame",
                                      r.frames ? 1000 * r.render_seconds / double(r.frames) : 0));
        report.push_back(number_entry(key + "error_seconds", r.error_seconds));
        report.push_back(number_entry(key + "seconds", r.total_seconds));
    }
    return report;
}

int run_city(const Arguments& arguments) {
    // Every input is checked before anything is generated or written.
    require(arguments.has("output"), "-o/--output OUTDIR is required");
    check_output_directory(arguments.text("output"));
    FlyThroughOptions options = fly_through_options(arguments);
    CityOptions city;
    city.buildings = arguments.integer("buildings");
    city.seed = std::uint64_t(arguments.integer("seed"));
    city.designs = arguments.integer("designs");
    const int frames = arguments.integer("frames");
    std::vector<double> details = details_option(arguments);
    std::string path_name = arguments.text("path");
    bool built_in = path_name == "orbit" || path_name == "street";
    std::vector<Keyframe> keys;
    if (!built_in) keys = load_keyframes(path_name);
    // An input named like a fly-through's file in OUTDIR would be replaced, or removed with the old run.
    for (const std::string& input :
         {built_in ? "" : path_name, arguments.positionals.empty() ? "" : arguments.positionals[0]})
        if (!input.empty())
            check_input_kept(input, arguments.text("output"), is_fly_through_file,
                             "-o " + arguments.text("output"));
    CityPlan plan;
    if (arguments.positionals.empty()) {
        plan = plan_city(city);
    } else {  // a city from a file: its objects are the buildings
        for (const char* generated : {"buildings", "designs", "seed"})
            require(!arguments.has(generated), std::string("--") + generated + ": a city read from " +
                                                   arguments.positionals[0] + " has its own buildings");
        plan = plan_from_model(read_model(arguments.positionals[0], options.levels.city_lod));
    }
    if (built_in) check_city_path(path_name, plan);
    check_memory("boxlod city: a fly-through of " + std::to_string(plan.lots.size()) + " buildings",
                 fly_through_memory(plan, options));
    CityLevels levels = build_city_levels(plan, options, needs_measured_errors(options.strategy), stderr);
    std::vector<CameraPose> path = built_in ? city_path(path_name, plan, levels.bounds, options.fovy, frames)
                                            : sample_keyframes(keys, frames);
    const std::string& output = arguments.text("output");
    OutputFolder folder(output,
                        is_fly_through_file);  // the old fly-through's files until the new ones are complete
    std::vector<FlyThroughReport> runs =
        run_fly_through(levels, path, options, details, folder.path(), stderr);
    folder.commit();
    KeyValues report = city_report(runs, options, output, path_name);
    print_report(report, arguments);
    return 0;
}

// The city's own options, the LoD parameters a city uses, then those it shares with other commands.
std::vector<Option> city_options() {
    std::vector<Option> options = {
        {"output",
         "OUTDIR",
         "folder for frames/, contact_sheet.png, frames.csv, timings.csv (required)",
         {},
         "",
         'o'},
        {"buildings", "N", "buildings in the city", city_buildings_range,
         std::to_string(CityOptions{}.buildings)},
        designs_option(),
        {"seed", "S", "the city's seed", seed_range, std::to_string(CityOptions{}.seed)},
        {"strategy", "S",
         "distance:D1,D2,... | pixels:P1,P2,... | ratio:R1,R2,... | "
         "diagonal[:MIN,MAX[,linear|square|square-root]] | texel[:ERROR_BUDGET] | measured[:ERROR] (each "
         "level from where its chain measured it within ERROR of the original, 0.05, as build --chain "
         "switches)",
         std::nullopt, format_strategy(FlyThroughOptions{}.strategy)},
        {"path", "PATH", "orbit, street, or a keyframe file of 'time x y z tx ty tz' lines", std::nullopt,
         "orbit"},
        {"frames", "F", "frames along the path", NumberRange{1, 100000}, "60"},
        {"width", "W", "frame width in pixels", NumberRange{16, 8192},
         std::to_string(FlyThroughOptions{}.width)},
        {"height", "H", "frame height in pixels, also the texture sizing resolution", NumberRange{16, 8192},
         std::to_string(FlyThroughOptions{}.height)},
        {"fovy", "DEGREES", "vertical field of view", parameter_range::fovy,
         format_number(FlyThroughOptions{}.fovy)},
        {"hysteresis", "H", "relative margin before a level changes back", NumberRange{0, 10},
         format_number(FlyThroughOptions{}.hysteresis)},
        {"detail", "K[,K...]",
         "level-of-detail bias: levels picked as if every building were 1/K as far (K > 1 finer, < 1 "
         "coarser; default 1); several: one run each over the same levels (at most 64), images under "
         "OUTDIR/detail_K/"},
        {"budget", "FACES",
         "most faces drawn per frame, streets included: least important buildings coarsened first",
         NumberRange{1, 1e9}},
        {"error-every", "K", "compare frames 0, K, 2K, ... with full detail (0: never)", NumberRange{0, 1e6},
         std::to_string(FlyThroughOptions{}.error_every)},
        {"ppd", "P", "FLIP's pixels per degree", pixels_per_degree_range,
         format_number(FlyThroughOptions{}.pixels_per_degree)},
    };
    options = with_options(options, lod_options(city_lod_parameters));
    return with_options(
        options, {
                     {"base-distance", "D", "level 1 is baked for D metres, level c for D x 2^(c-1)",
                      NumberRange{1e-2, 1e6}, format_number(FlyThroughOptions{}.base_distance)},
                     {"memory", "MB",
                      "unpacked levels kept between frames, in MiB; levels are kept packed (deflated) and a "
                      "frame's own levels are always unpacked",
                      NumberRange{0, 1 << 20}, std::to_string(FlyThroughOptions{}.memory_budget >> 20)},
                     threads_option(),
                     json_option(),
                 });
}

}  // namespace

Subcommand city_subcommand() {
    return {{"city", "[CITY]",
             "Fly through a city with run-time LoD selection: a generated one, or CITY, a model whose root's "
             "children are its buildings (a CityJSON district's Buildings, a glTF city), without streets. "
             "Every building gets its own LoD, built once (level c baked for --base-distance x 2^(c-1)); per "
             "frame the strategy picks each building's level (with hysteresis, optionally under a face "
             "budget). Writes OUTDIR/frames/frame_NNNN.png, OUTDIR/contact_sheet.png, OUTDIR/frames.csv "
             "(faces, level histogram, levels changed, PSNR/SSIM/FLIP against full detail on sampled frames; "
             "identical for any thread count) and OUTDIR/timings.csv. With several --detail values, one pass "
             "each over the same levels (images under OUTDIR/detail_K/).",
             city_options(), 0, 1},
            run_city};
}

}  // namespace boxlod
