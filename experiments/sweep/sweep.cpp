#include "experiments/sweep/sweep.h"
#include "experiments/sweep/sweep_baselines.h"
#include "experiments/sweep/sweep_group.h"

#include "base/csv.h"
#include "base/input_error.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "experiments/sweep/file_lods.h"
#include "experiments/sweep/sweep_shots.h"
#include "experiments/sweep/sweep_tables.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/cut/level_values.h"
#include "toolkit/metrics/metric_registry.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/framing.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

Model load_sweep_model(const SweepModel& model) {
    if (!model.sample.empty()) return generate_building(sample_grammar(model.sample), BuildingOptions{});
    return load_model(model.path);
}

}  // namespace

std::vector<std::string> result_columns(const SweepConfig& config) {
    std::vector<std::string> columns = sweep_key_columns();
    for (const char* c :
         {"obtained_levels", "faces", "triangles", "vertices", "batches", "texels", "face_texels", "pages",
          "largest_page", "nodes_with_box", "depth_error", "measured_error", "draw_calls", "mesh_bytes",
          "texture_bytes", "texture_bytes_gpu", "bytes", "covered_pixels", "baseline_variant"})
        columns.push_back(c);
    for (Metric metric : config.metrics) columns.push_back(enum_name(metrics(), metric));
    return columns;
}

std::vector<std::string> timing_columns() {
    std::vector<std::string> columns = sweep_key_columns();
    for (const char* c : {"build_seconds", "render_seconds", "metric_seconds"}) columns.push_back(c);
    return columns;
}

namespace {

// The plan of one model: its variants (level mode x box kind x interpolation)
// with their levels, and how many groups of rows they and the baselines make.
struct ModelPlan {
    std::map<BoxKind, std::vector<std::optional<OrientedBox>>> boxes;  // once per box kind
    std::vector<SweepVariant> variants;
    std::size_t groups = 0;
};

ModelPlan plan_model(const SweepConfig& config, const Model& model, const std::string& model_path,
                     int threads) {
    ModelPlan plan;
    for (BoxKind kind : config.box_kinds) plan.boxes[kind] = node_boxes(model, kind, threads);
    for (LevelMode mode : config.level_modes)
        for (BoxKind kind : config.box_kinds)
            for (Interpolation interpolation : config.interpolations) {
                LodParameters asked = config.lod;
                asked.level_mode = mode;
                const int obtained = obtained_levels(model, mode, asked_levels(asked));
                SweepVariant variant{mode, kind, interpolation, obtained, {}};
                for (int level = 0; level <= obtained; ++level)
                    if (config.levels.empty() ||
                        std::binary_search(config.levels.begin(), config.levels.end(), level))
                        variant.levels.push_back(level);
                plan.groups += variant.levels.size();
                plan.variants.push_back(std::move(variant));
            }
    // The baselines follow the first variant: a simplified mesh per level, one single box at its top.
    const std::vector<int>& levels = plan.variants.front().levels;
    for (Baseline baseline : config.baselines)
        plan.groups += baseline == Baseline::file_lods
                           ? coarser_file_lods(config.lod.city_lod, model_path).size()
                       : baseline == Baseline::single_box || baseline == Baseline::impostor ? 1
                       : baseline == Baseline::proxy_baked
                           ? levels.size() - std::size_t(std::count(levels.begin(), levels.end(), 0))
                           : levels.size();
    return plan;
}

// The LoD levels of one variant. Normal, parallax, pom and albedo draw the same
// baked boxes; untextured boxes are not baked. Slot = 2 x sizing distance +
// (untextured ? 1 : 0); one chain per slot, shared by the levels: every level
// sized for the slot's distance, or (per_level sizing) level c for it x 2^(c-1), the chain's doubling
// (with budgets at most x B_1/B_c: chain.h, level_distances).
void run_variant(ModelRun& run, SweepOutput& out, SweepReport& report, const ModelPlan& plan,
                 const SweepVariant& variant) {
    const SweepConfig& config = run.config;
    // With SizingRule::nearest (and per_level) every distance draws the LoD baked for the smallest one.
    auto sizing_index = [&](std::size_t d) -> std::size_t {
        if (config.sizing == SizingRule::each_distance) return d;
        return std::size_t(std::min_element(config.distances.begin(), config.distances.end()) -
                           config.distances.begin());
    };
    std::map<int, std::unique_ptr<Chain>> chains;
    auto slot = [&](RenderMode mode, std::size_t, std::size_t d) {
        return int(2 * sizing_index(d) + (mode == RenderMode::untextured));
    };
    for (int level : variant.levels) {
        std::string group =
            csv_row({run.entry.name, level_mode_name(variant.mode), box_kind_name(variant.box),
                     interpolation_name(variant.interpolation), std::to_string(level)});
        run_group(run, out, report, group, slot, [&](int s, int) {
            std::unique_ptr<Chain>& chain = chains[s];
            if (!chain) {
                LodParameters p = config.lod;
                p.level_mode = variant.mode;
                p.box_kind = variant.box;
                p.interpolation = variant.interpolation;
                p.distance =  // level 1's, within range
                    float(doubled_distance(
                        config.distances[std::size_t(s / 2)] * framing_distance(run.framing, p.fovy), 1));
                p.level_distances.rule = config.sizing == SizingRule::per_level
                                             ? LevelDistances::Rule::doubling
                                             : LevelDistances::Rule::same;
                p.render_mode = s % 2 ? RenderMode::untextured : RenderMode::normal;
                if (!orders_by_bytes(p.level_mode))
                    p.budgets.clear();  // the other modes make wanted_levels levels
                // A row over its budget says so in its bytes.
                chain = std::make_unique<Chain>(run.model, p, run.threads,
                                                ChainOptions{&plan.boxes.at(variant.box), false});
            }
            Lod lod = chain->build(level);
            SweepCandidate c = candidate(std::move(lod.model), std::move(lod.atlas), lod.cut.box_nodes.size(),
                                         variant.obtained_levels, &lod.cost);
            c.face_texels = lod.face_texels;
            c.depth_error = format_number(lod.depth_error);
            if (variant.mode == LevelMode::hybrid) c.measured_error = format_number(lod.measured_error);
            return c;
        });
    }
}

// Plan, then execute, model by model, into the results table (after the shards' rows, if any).
SweepReport sweep_into(const SweepConfig& config, const std::string& output_folder, int threads,
                       std::FILE* progress, const std::vector<std::string>& shard_folders = {}) {
    auto sweep_start = Clock::now();
    if (threads < 0) threads = config.threads;
    // Rows are drawn `threads` at a time, each rendering (supersampled) and comparing with its view's
    // reference, which is rendered the same way.
    const int side_by_side = thread_count(threads);
    const int k = config.supersampling;
    check_memory("boxlod sweep: " + std::to_string(side_by_side) + " views of " +
                     std::to_string(config.width * k) + "x" + std::to_string(config.height * k) + " pixels",
                 side_by_side * (2 * render_memory(config.width * k, config.height * k) +
                                 metrics_memory(config.width, config.height)));
    const double most_rows =
        most_sweep_rows(config);  // refused before a model is read, an enormous one ran until killed
    check_memory("boxlod sweep: the tables of up to " + format_number(most_rows) + " rows",
                 most_rows * sweep_row_memory);
    SweepReport report;
    SweepOutput out = open_output(config, output_folder, result_columns(config), timing_columns());
    merge_shards(out, shard_folders);
    for (std::size_t m = 0; m < config.models.size(); ++m) {
        Model model = load_sweep_model(config.models[m]);
        ModelPlan plan = timed(report.boxes_seconds,
                               [&] { return plan_model(config, model, config.models[m].path, threads); });
        if (progress && m == 0)  // once a model is read: a sweep refused for it says so in one line
            std::fprintf(progress, "boxlod sweep: up to %s rows; each model's lines give its ETA\n",
                         format_number(most_rows).c_str());
        ModelRun run{config, config.models[m], model, model_framing(model)};
        run.index = m;
        run.rows = plan.groups * rows_per_group(config);
        run.threads = threads;
        run.progress = progress;
        report.rows += run.rows;
        for (const SweepVariant& variant : plan.variants) run_variant(run, out, report, plan, variant);
        run_baselines(run, out, report, plan.variants.front());
    }
    write_tables(out);
    report.total_seconds = seconds_since(sweep_start);
    return report;
}

}  // namespace

SweepReport run_sweep(const SweepConfig& config, const std::string& output_folder, int threads,
                      std::FILE* progress) {
    return merge_sweep(config, {}, output_folder, threads, progress);
}

SweepReport merge_sweep(const SweepConfig& config, const std::vector<std::string>& shard_folders,
                        const std::string& output_folder, int threads, std::FILE* progress) {
    // A sweep that fails before its first row (a model that cannot be read)
    // leaves no folder behind; rows computed stay, for the next run to resume.
    const bool new_folder = !fs::exists(output_folder);
    try {
        return sweep_into(config, output_folder, threads, progress, shard_folders);
    } catch (...) {
        std::error_code ignored;
        if (new_folder && !fs::exists(fs::path(output_folder) / "results.csv", ignored))
            fs::remove_all(output_folder, ignored);
        throw;
    }
}

}  // namespace boxlod
