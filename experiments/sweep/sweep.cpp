#include "experiments/sweep/sweep.h"

#include "base/csv.h"
#include "base/memory_budget.h"
#include "base/parallel.h"
#include "base/input_error.h"
#include "base/key_values.h"
#include "base/timing.h"
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/heatmap.h"
#include "experiments/sweep/file_lods.h"
#include "experiments/sweep/impostor.h"
#include "experiments/sweep/proxy_baked.h"
#include "toolkit/metrics/image_metrics.h"
#include "toolkit/metrics/metric_registry.h"
#include "toolkit/metrics/silhouette.h"
#include "experiments/sweep/sweep_shots.h"
#include "experiments/sweep/sweep_tables.h"
#include "experiments/sweep/within_budget.h"
#include "toolkit/lod/cut/level_values.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/hybrid/simplification.h"
#include "experiments/sweep/single_box.h"
#include "toolkit/cgal/cgal_simplification.h"
#include "toolkit/model/cost.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/model/framing.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/statistics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace boxlod {
namespace {

namespace fs = std::filesystem;

// A row key (CSV text already) extended by more fields.
std::string extend_row(const std::string& key, const std::vector<std::string>& more) { return key + "," + csv_row(more); }

Model load_sweep_model(const SweepModel& model) {
    if (!model.sample.empty()) return generate_building(sample_grammar(model.sample), BuildingOptions{});
    return load_model(model.path);
}

// What one group of rows draws: an LoD level or a baseline mesh.
struct Candidate {
    Model model;
    Atlas atlas;  // pages = 0 for untextured boxes and the baselines
    std::uint64_t face_texels = 0;  // the baked faces' own texels, without the atlas's gutters and free space
    std::size_t nodes_with_box = 0;
    std::string depth_error;  // an LoD's proxy error (LodDerived::depth_errors summed over its boxes); empty for baselines
    std::string measured_error;  // a hybrid level's measured proxy error (Lod::measured_error); empty for the others
    int obtained_levels = 0;
    CostParts cost;  // each row states the cost of the maps its render mode draws
    std::unique_ptr<DrawableModel> drawable;  // made by run_group unless `make` made it
    double seconds = 0;  // building it and making it drawable
    std::string variant;  // a baseline's variant (results.csv baseline_variant)
};

// `cost`: the model's, when its builder has it already (an LoD); else computed here.
Candidate candidate(Model model, Atlas atlas, std::size_t nodes_with_box, int obtained_levels, const CostParts* cost = nullptr) {
    Candidate c;
    c.cost = cost ? *cost : cost_parts(model);
    c.model = std::move(model);
    c.atlas = std::move(atlas);
    c.nodes_with_box = nodes_with_box;
    c.obtained_levels = obtained_levels;
    return c;
}

// The `triangles` column of a results.csv row (after the key columns, obtained_levels and faces).
std::size_t triangles_of_row(const std::string& row) { return std::stoull(csv_fields(row).at(sweep_key_columns().size() + 2)); }

struct Variant {
    LevelMode mode;
    BoxKind box;
    Interpolation interpolation;
    int obtained_levels = 1;
    std::vector<int> levels;
};

std::string eta_text(double seconds) {
    int s = int(seconds + 0.5);
    std::ostringstream out;
    if (s >= 3600) out << s / 3600 << "h";
    if (s >= 60) out << s / 60 % 60 << "m";
    out << s % 60 << "s";
    return out.str();
}

}  // namespace

std::vector<std::string> result_columns(const SweepConfig& config) {
    std::vector<std::string> columns = sweep_key_columns();
    for (const char* c : {"obtained_levels", "faces", "triangles", "vertices", "batches", "texels", "face_texels", "pages", "largest_page",
                          "nodes_with_box", "depth_error", "measured_error", "draw_calls", "mesh_bytes", "texture_bytes", "texture_bytes_gpu", "bytes",
                          "covered_pixels", "baseline_variant"})
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
    std::vector<Variant> variants;
    std::size_t groups = 0;
};

ModelPlan plan_model(const SweepConfig& config, const Model& model, const std::string& model_path, int threads) {
    ModelPlan plan;
    for (BoxKind kind : config.box_kinds) plan.boxes[kind] = node_boxes(model, kind, threads);
    for (LevelMode mode : config.level_modes)
        for (BoxKind kind : config.box_kinds)
            for (Interpolation interpolation : config.interpolations) {
                LodParameters asked = config.lod;
                asked.level_mode = mode;
                const int obtained = obtained_levels(model, mode, asked_levels(asked));
                Variant variant{mode, kind, interpolation, obtained, {}};
                for (int level = 0; level <= obtained; ++level)
                    if (config.levels.empty() || std::binary_search(config.levels.begin(), config.levels.end(), level))
                        variant.levels.push_back(level);
                plan.groups += variant.levels.size();
                plan.variants.push_back(std::move(variant));
            }
    // The baselines follow the first variant: a simplified mesh per level, one single box at its top.
    const std::vector<int>& levels = plan.variants.front().levels;
    for (Baseline baseline : config.baselines)
        plan.groups += baseline == Baseline::file_lods ? coarser_file_lods(config.lod.city_lod, model_path).size()
                       : baseline == Baseline::single_box || baseline == Baseline::impostor ? 1
                       : baseline == Baseline::proxy_baked ? levels.size() - std::size_t(std::count(levels.begin(), levels.end(), 0))
                                                           : levels.size();
    return plan;
}

// The executor's state for one model: the original's renders (per view,
// distance and mode, made when first needed) and the progress counters.
struct ModelRun {
    const SweepConfig& config;
    const SweepModel& entry;
    const Model& model;
    Framing framing;
    std::size_t index = 0, rows = 0, done = 0, computed = 0;
    double seconds = 0;
    int threads = 0;
    std::FILE* progress = nullptr;
    std::unique_ptr<DrawableModel> original = nullptr;
    std::map<std::tuple<std::size_t, std::size_t, RenderMode>, Shot> references = {};
};

std::size_t rows_per_group(const SweepConfig& config) {
    return config.views.size() * config.distances.size() * config.render_modes.size();
}

// The results.csv fields of a row after its key.
std::vector<std::string> result_fields(const Candidate& c, RenderMode mode, const Shot& original, const Metrics& metrics) {
    const ModelCost cost = drawn_cost({&c.cost}, mode);
    MeshCounts counts = mesh_counts(c.model);
    int largest_page = 0;
    for (const Eigen::Vector2i& page : c.atlas.pages) largest_page = std::max({largest_page, page.x(), page.y()});
    std::vector<std::string> fields = {
        std::to_string(c.obtained_levels),
        std::to_string(counts.faces), std::to_string(counts.triangles), std::to_string(counts.vertices),
        std::to_string(counts.batches), std::to_string(page_texels(c.atlas)),
        std::to_string(c.face_texels),
        std::to_string(c.atlas.pages.size()), std::to_string(largest_page),
        std::to_string(c.nodes_with_box), c.depth_error, c.measured_error, std::to_string(cost.draw_calls), std::to_string(cost.mesh_bytes),
        std::to_string(cost.texture_bytes), std::to_string(cost.texture_bytes_gpu), std::to_string(cost.bytes()),
        std::to_string(covered_pixels(original.coverage)), c.variant};
    fields.insert(fields.end(), metrics.values.begin(), metrics.values.end());
    return fields;
}

// A row of a group, not yet in results.csv.
struct MissingRow { std::size_t view, distance; RenderMode mode; std::string key; };

// The group's rows in the sweep's order (noted in `out.order`); those
// results.csv holds already are counted as skipped, the others returned.
std::vector<MissingRow> missing_rows(ModelRun& run, SweepOutput& out, SweepReport& report, const std::string& group) {
    const SweepConfig& config = run.config;
    std::vector<MissingRow> missing;
    for (std::size_t v = 0; v < config.views.size(); ++v)
        for (std::size_t d = 0; d < config.distances.size(); ++d)
            for (RenderMode mode : config.render_modes) {
                std::string key = extend_row(group, {config.views[v], format_number(config.distances[d]), render_mode_name(mode)});
                out.order.push_back(key);
                if (!out.results.rows.count(key)) missing.push_back({v, d, mode, key});
            }
    const std::size_t skipped = rows_per_group(config) - missing.size();
    report.rows_skipped += skipped;
    run.done += skipped;
    return missing;
}

// The original's renders that the rows need and the run has not made yet,
// drawn as the rows are (draw_rows), in the rows' order.
void make_reference_shots(ModelRun& run, SweepOutput& out, SweepReport& report, const std::vector<MissingRow>& rows) {
    const SweepConfig& config = run.config;
    std::vector<std::tuple<std::size_t, std::size_t, RenderMode>> keys;
    for (const MissingRow& row : rows) {
        auto key = std::make_tuple(row.view, row.distance, row.mode);
        if (!run.references.count(key) && std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
    if (keys.empty()) return;
    if (!run.original) run.original = make_drawable_model(run.model);
    const bool flip_measured = std::find(config.metrics.begin(), config.metrics.end(), Metric::flip) != config.metrics.end();
    std::vector<Shot> shots(keys.size());
    std::vector<double> render_seconds(keys.size(), 0), metric_seconds(keys.size(), 0);
    parallel_for(keys.size(), run.threads, [&](std::size_t k) {
        const auto [v, d, mode] = keys[k];
        const RenderSettings settings = view_settings(run.framing, config.views[v], config.distances[d], mode, config.lod, 1);
        shots[k] = timed(render_seconds[k],
                         [&] { return render_shot(run.original->drawable.batches, settings, config.width, config.height); });
        if (flip_measured)
            shots[k].flip_reference =
                timed(metric_seconds[k], [&] { return prepare_flip_reference(shots[k].image, config.pixels_per_degree, 1); });
    });
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const auto [v, d, mode] = keys[k];
        report.render_seconds += render_seconds[k];
        report.metric_seconds += metric_seconds[k];
        ++report.original_renders;
        if (out.keep_images)
            save_image(out, csv_row({run.entry.name, "original", config.views[v], format_number(config.distances[d]), render_mode_name(mode)}),
                       shots[k].image);
        run.references.emplace(keys[k], std::move(shots[k]));
    }
}

// A row as drawn: its results.csv and timings.csv lines, its image and heat map, its choice_error.
struct DrawnRow {
    std::string result, timing;
    Image8 image;
    Plane heatmap;
    double error = 0, render_seconds = 0, metric_seconds = 0;
};

// One row on the calling thread: the candidate rendered from the row's view
// and compared with the original's render.
DrawnRow draw_row(const ModelRun& run, bool keep_image, const Candidate& c, const MissingRow& row) {
    const SweepConfig& config = run.config;
    const Shot& original_shot = run.references.at({row.view, row.distance, row.mode});
    const RenderSettings settings =
        view_settings(run.framing, config.views[row.view], config.distances[row.distance], row.mode, config.lod, 1);
    DrawnRow drawn;
    Shot shot = timed(drawn.render_seconds,
                      [&] { return render_shot(c.drawable->drawable.batches, settings, config.width, config.height); });
    Metrics metrics = timed(drawn.metric_seconds,
                            [&] { return compare_shots(config, original_shot, shot, config.keep_images == KeptImages::all, 1); });
    drawn.result = extend_row(row.key, result_fields(c, row.mode, original_shot, metrics));
    drawn.timing =
        extend_row(row.key, {format_number(c.seconds), format_number(drawn.render_seconds), format_number(drawn.metric_seconds)});
    if (keep_image) drawn.image = std::move(shot.image);
    drawn.heatmap = std::move(metrics.heatmap);
    drawn.error = metrics.error;
    return drawn;
}

// The rows, `candidates[r]` drawing row r: each row on one thread, the rows
// side by side. Small renders and their metrics gain more so than from
// splitting one image among threads (docs/performance.md: Sweep); every
// pixel and metric is the same.
std::vector<DrawnRow> draw_rows(ModelRun& run, SweepOutput& out, SweepReport& report,
                                const std::vector<const Candidate*>& candidates, const std::vector<MissingRow>& rows) {
    make_reference_shots(run, out, report, rows);
    std::vector<DrawnRow> drawn(rows.size());
    parallel_for(rows.size(), run.threads, [&](std::size_t r) { drawn[r] = draw_row(run, out.keep_images, *candidates[r], rows[r]); });
    for (const DrawnRow& row : drawn) report.render_seconds += row.render_seconds, report.metric_seconds += row.metric_seconds;
    report.lod_renders += rows.size();
    return drawn;
}

// The group's line on the progress stream, with the model's ETA.
void report_group(const ModelRun& run, const std::string& group, std::size_t rows, double seconds) {
    if (!run.progress) return;
    const double eta = run.seconds / double(run.computed) * double(run.rows - run.done);
    std::fprintf(run.progress, "boxlod sweep: model %zu/%zu %s: %zu rows in %.2f s; %zu/%zu rows of this model, ETA %s\n",
                 run.index + 1, run.config.models.size(), group.c_str(), rows, seconds, run.done, run.rows,
                 eta_text(eta).c_str());
    std::fflush(run.progress);
}

// A group: the rows of one drawn candidate (an LoD level, a simplified mesh, the single box)
// over views x distances x render modes. `slot(mode, view, distance)` says which rows may
// share one candidate, `make(slot, alternative)` builds it; both run only for rows missing
// from results.csv.
// With several `alternatives` (simplification-best), each is drawn for every missing row
// and the group keeps the one with the lowest mean choice_error over them, of
// those within `budget` bytes (every texture) where there are any.
void run_group(ModelRun& run, SweepOutput& out, SweepReport& report, const std::string& group,
               const std::function<int(RenderMode, std::size_t, std::size_t)>& slot,
               const std::function<Candidate(int, int)>& make,
               int alternatives = 1, double budget = -1) {
    auto group_start = Clock::now();
    const std::vector<MissingRow> missing = missing_rows(run, out, report, group);
    if (missing.empty()) return;
    std::vector<std::vector<DrawnRow>> drawn(static_cast<std::size_t>(alternatives));
    std::vector<double> mean_error(std::size_t(alternatives), 0);
    std::vector<char> fits(std::size_t(alternatives), true);
    for (int a = 0; a < alternatives; ++a) {
        std::map<int, Candidate> candidates;
        std::vector<const Candidate*> of_row;
        for (const MissingRow& row : missing) {
            int s = slot(row.mode, row.view, row.distance);
            auto found = candidates.find(s);
            if (found == candidates.end()) {
                double seconds = 0;
                Candidate made = timed(seconds, [&] {
                    Candidate built = make(s, a);
                    if (!built.drawable) built.drawable = make_drawable_model(built.model);
                    return built;
                });
                made.seconds = seconds;
                report.build_seconds += seconds;
                ++report.lods_built;
                found = candidates.emplace(s, std::move(made)).first;
            }
            of_row.push_back(&found->second);
            if (budget >= 0 && double(combined_cost({&found->second.cost}).bytes()) > budget) fits[std::size_t(a)] = false;
        }
        drawn[std::size_t(a)] = draw_rows(run, out, report, of_row, missing);
        for (const DrawnRow& row : drawn[std::size_t(a)]) mean_error[std::size_t(a)] += row.error / double(missing.size());
    }
    const bool any_fits = std::find(fits.begin(), fits.end(), true) != fits.end();
    std::size_t best = fits.size();  // the first of the lowest error among those within the budget, or all where none is
    for (std::size_t a = 0; a < fits.size(); ++a)
        if ((fits[a] || !any_fits) && (best == fits.size() || mean_error[a] < mean_error[best])) best = a;
    for (std::size_t r = 0; r < missing.size(); ++r) {
        DrawnRow& row = drawn[best][r];
        out.results.rows[missing[r].key] = row.result;
        out.timings.rows[missing[r].key] = row.timing;
        if (out.keep_images) save_image(out, missing[r].key, row.image);
        if (run.config.keep_images == KeptImages::all) save_image(out, missing[r].key + "_heatmap", error_heatmap(row.heatmap));
    }
    write_tables(out);
    report.rows_computed += missing.size();
    run.done += missing.size();
    run.computed += missing.size();
    const double group_seconds = seconds_since(group_start);
    run.seconds += group_seconds;
    report_group(run, group, missing.size(), group_seconds);
}

// The LoD levels of one variant. Normal, parallax, pom and albedo draw the same
// baked boxes; untextured boxes are not baked. Slot = 2 x sizing distance +
// (untextured ? 1 : 0); one session per slot and sizing level, shared by the
// levels (per_level sizing: one per level, baked for the nearest distance x 2^(level-1)).
void run_variant(ModelRun& run, SweepOutput& out, SweepReport& report, const ModelPlan& plan, const Variant& variant) {
    const SweepConfig& config = run.config;
    // With SizingRule::nearest (and per_level) every distance draws the LoD baked for the smallest one.
    auto sizing_index = [&](std::size_t d) -> std::size_t {
        if (config.sizing == SizingRule::each_distance) return d;
        return std::size_t(std::min_element(config.distances.begin(), config.distances.end()) - config.distances.begin());
    };
    std::map<std::pair<int, int>, std::unique_ptr<LodSession>> sessions;
    auto slot = [&](RenderMode mode, std::size_t, std::size_t d) {
        return int(2 * sizing_index(d) + (mode == RenderMode::untextured));
    };
    for (int level : variant.levels) {
        const int sizing_level = config.sizing == SizingRule::per_level ? std::max(level, 1) : 1;
        std::string group = csv_row({run.entry.name, level_mode_name(variant.mode), box_kind_name(variant.box),
                                     interpolation_name(variant.interpolation), std::to_string(level)});
        run_group(run, out, report, group, slot, [&](int s, int) {
            std::unique_ptr<LodSession>& session = sessions[{s, sizing_level}];
            if (!session) {
                LodParameters p = config.lod;
                p.level_mode = variant.mode;
                p.box_kind = variant.box;
                p.interpolation = variant.interpolation;
                p.distance = float(doubled_distance(config.distances[std::size_t(s / 2)] * framing_distance(run.framing, p.fovy),
                                                    sizing_level));
                p.render_mode = s % 2 ? RenderMode::untextured : RenderMode::normal;
                if (!orders_by_bytes(p.level_mode)) p.budgets.clear();  // the other modes make wanted_levels levels
                session = start_lod(run.model, p, run.threads, &plan.boxes.at(variant.box));
                session->input.budgets_strict = false;  // a row over its budget says so in its bytes
            }
            Lod lod = build_lod(*session, level, run.threads);
            Candidate c = candidate(std::move(lod.model), std::move(lod.atlas), lod.cut.box_nodes.size(),
                                    variant.obtained_levels, &lod.cost);
            c.face_texels = lod.face_texels;
            c.depth_error = format_number(lod.depth_error);
            if (variant.mode == LevelMode::hybrid) c.measured_error = format_number(lod.measured_error);
            return c;
        });
    }
}

// The impostor: one atlas per model, captured for texel = pixel at the nearest of the
// distances; each view and distance draws the quad of the direction nearest its camera.
// file-lods: each of a CityJSON model's LoDs coarser than the one read, a group of its own.
void run_file_lods(ModelRun& run, SweepOutput& out, SweepReport& report, int obtained_levels) {
    auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
    const std::vector<std::string> lods = coarser_file_lods(run.config.lod.city_lod, run.entry.path);
    for (std::size_t k = 0; k < lods.size(); ++k)
        run_group(run, out, report, csv_row({run.entry.name, "file-lods", "-", "-", std::to_string(k + 1)}), one_slot, [&](int, int) {
            Candidate c = candidate(load_model(run.entry.path, {.chain_level = 0, .city_lod = lods[k]}), {}, 0, obtained_levels);
            c.variant = "LoD " + lods[k];
            return c;
        });
}

void run_impostor(ModelRun& run, SweepOutput& out, SweepReport& report, const std::string& group, int level) {
    const SweepConfig& config = run.config;
    std::optional<ImpostorAtlas> atlas;
    TextureCache decoded;  // every view's quad draws the same atlas: decoded once
    auto view_slot = [&](RenderMode, std::size_t v, std::size_t d) { return int(v * config.distances.size() + d); };
    run_group(run, out, report, group, view_slot, [&](int s, int) {
        const std::size_t v = std::size_t(s) / config.distances.size(), d = std::size_t(s) % config.distances.size();
        if (!atlas) {
            TextureSizing sizing;
            sizing.fovy_degrees = config.lod.fovy;
            sizing.resolution = config.lod.resolution;
            sizing.distance = *std::min_element(config.distances.begin(), config.distances.end()) *
                              framing_distance(run.framing, config.lod.fovy);
            int cell = impostor_cell(model_bounds(run.model), pixel_world_size(sizing));
            atlas = make_impostor(run.model, config.impostor_directions, cell, run.threads);
        }
        Eigen::Vector3f eye = view_settings(run.framing, config.views[v], config.distances[d], RenderMode::normal,
                                            config.lod, run.threads).camera.position;
        Candidate c = candidate(impostor_model(*atlas, eye, run.model.source), {}, 0, level);
        c.variant = "direction " + std::to_string(nearest_direction(*atlas, eye));
        c.drawable = make_drawable_model(c.model, &decoded, run.threads);
        return c;
    });
}

// Levels by byte budget: a baseline's level c >= 1 as finely as budget c
// allows (equal bytes, not equal triangles), in bytes; -1 where levels are not by budget.
double level_budget(const ModelRun& run, const Variant& first, int level) {
    const LodParameters& lod = run.config.lod;
    if (!orders_by_bytes(first.mode) || lod.budgets.empty() || level == 0) return -1;
    return budget_bytes(lod.budgets[std::size_t(level - 1)], double(model_cost(run.model).bytes()));
}

// proxy-baked: per level but the original (a baked copy of it is no level)
// the best of its variants that fit the level's budget (or at its
// triangles), baked as the first variant's level is sized (sizing
// each-distance: for the nearest distance, as the impostor; one session per
// sizing level, which bakes the root's box once).
void run_proxy_baked(ModelRun& run, SweepOutput& out, SweepReport& report, const Variant& first,
                     const std::function<std::size_t(int)>& triangles_of_level) {
    const SweepConfig& config = run.config;
    const std::vector<ProxyBakedVariant> variants = proxy_baked_variants(run.threads);
    const double nearest = *std::min_element(config.distances.begin(), config.distances.end()) * framing_distance(run.framing, config.lod.fovy);
    std::map<int, std::unique_ptr<LodSession>> sessions;  // per sizing level
    for (int level : first.levels) {
        if (level == 0) continue;
        const int sizing_level = config.sizing == SizingRule::per_level ? level : 1;
        const double budget = level_budget(run, first, level);
        auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
        const std::string group = csv_row({run.entry.name, "proxy-baked", "-", "-", std::to_string(level)});
        run_group(run, out, report, group, one_slot, [&](int, int a) {
            std::unique_ptr<LodSession>& session = sessions[sizing_level];
            if (!session)
                session = start_lod(run.model, proxy_baked_parameters(config.lod, float(doubled_distance(nearest, sizing_level))), run.threads);
            const ProxyBakedVariant& v = variants[std::size_t(a)];
            Lod lod = proxy_baked_level(*session, v, triangles_of_level(level), budget, level, run.threads);
            Candidate c = candidate(std::move(lod.model), std::move(lod.atlas), 0, first.obtained_levels, &lod.cost);
            c.face_texels = lod.face_texels;
            c.variant = v.name;
            return c;
        }, int(variants.size()), budget);
    }
}

// The baselines: the same rows, drawn by a mesh that depends on no view, distance or mode.
void run_baselines(ModelRun& run, SweepOutput& out, SweepReport& report, const Variant& first) {
    const SweepConfig& config = run.config;
    auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
    // The triangles of `level` of the first variant, as its first row says.
    auto triangles_of_level = [&](int level) {
        return triangles_of_row(out.results.rows.at(csv_row(
            {run.entry.name, level_mode_name(first.mode), box_kind_name(first.box), interpolation_name(first.interpolation),
             std::to_string(level), config.views[0], format_number(config.distances[0]),
             render_mode_name(config.render_modes[0])})));
    };
    const std::vector<SimplifyVariant> variants = simplify_variants(run.threads);
    for (const EnumEntry<Baseline>& entry : baselines()) {  // in the table's order, whatever the config's
        const Baseline baseline = entry.value;
        const std::string name = entry.name;
        if (std::find(config.baselines.begin(), config.baselines.end(), baseline) == config.baselines.end()) continue;
        const std::string top_group = csv_row({run.entry.name, name, "-", "-", std::to_string(first.obtained_levels)});
        if (baseline == Baseline::single_box) {
            run_group(run, out, report, top_group, one_slot, [&](int, int) {
                return candidate(single_box_model(run.model, run.threads), {}, 0, first.obtained_levels);
            });
            continue;
        }
        if (baseline == Baseline::impostor || baseline == Baseline::file_lods || baseline == Baseline::proxy_baked) {  // their own groups
            if (baseline == Baseline::impostor) run_impostor(run, out, report, top_group, first.obtained_levels);
            else if (baseline == Baseline::proxy_baked) run_proxy_baked(run, out, report, first, triangles_of_level);
            else run_file_lods(run, out, report, first.obtained_levels);
            continue;
        }
        // simplification: the first variant (boxlod simplify's); simplification-best: the best of all.
        const int alternatives = baseline == Baseline::simplification_best ? int(variants.size()) : 1;
        for (int level : first.levels) {
            const std::size_t target = triangles_of_level(level);
            const double budget = level_budget(run, first, level);
            auto simplified = [&](const std::function<Model(std::size_t)>& simplify) {  // bytes: cost.h, every texture
                if (budget < 0) return simplify(target);
                return finest_within<Model>(mesh_counts(run.model).triangles, budget, simplify,
                                            [](const Model& model) { return double(model_cost(model).bytes()); });
            };
            run_group(run, out, report, csv_row({run.entry.name, name, "-", "-", std::to_string(level)}), one_slot,
                      [&](int, int a) {
                          if (baseline == Baseline::cgal) {
                              Candidate c = candidate(simplified([&](std::size_t t) { return cgal_simplify(run.model, t); }),
                                                      {}, 0, first.obtained_levels);
                              c.variant = "garland-heckbert";
                              return c;
                          }
                          const SimplifyVariant& v = variants[std::size_t(a)];
                          Candidate c = candidate(
                              simplified([&](std::size_t t) { return simplify_model(run.model, t, v.options); }), {}, 0,
                              first.obtained_levels);
                          c.variant = v.name;
                          return c;
                      },
                      alternatives, budget);
        }
    }
}

// Plan, then execute, model by model, into the results table (after the shards' rows, if any).
SweepReport sweep_into(const SweepConfig& config, const std::string& output_folder, int threads, std::FILE* progress,
                       const std::vector<std::string>& shard_folders = {}) {
    auto sweep_start = Clock::now();
    if (threads < 0) threads = config.threads;
    // A row holds its view's reference shot and the one it measures, both compared.
    check_memory("boxlod sweep: views of " + std::to_string(config.width) + "x" + std::to_string(config.height) + " pixels",
                 2 * render_memory(config.width, config.height) + metrics_memory(config.width, config.height));
    const double most_rows = most_sweep_rows(config);  // refused before a model is read, an enormous one ran until killed
    check_memory("boxlod sweep: the tables of up to " + format_number(most_rows) + " rows", most_rows * sweep_row_memory);
    SweepReport report;
    SweepOutput out = open_output(config, output_folder, result_columns(config), timing_columns());
    merge_shards(out, shard_folders);
    for (std::size_t m = 0; m < config.models.size(); ++m) {
        Model model = load_sweep_model(config.models[m]);
        ModelPlan plan = timed(report.boxes_seconds, [&] { return plan_model(config, model, config.models[m].path, threads); });
        if (progress && m == 0)  // once a model is read: a sweep refused for it says so in one line
            std::fprintf(progress, "boxlod sweep: up to %s rows; each model's lines give its ETA\n", format_number(most_rows).c_str());
        ModelRun run{config, config.models[m], model, model_framing(model)};
        run.index = m;
        run.rows = plan.groups * rows_per_group(config);
        run.threads = threads;
        run.progress = progress;
        report.rows += run.rows;
        for (const Variant& variant : plan.variants) run_variant(run, out, report, plan, variant);
        run_baselines(run, out, report, plan.variants.front());
    }
    write_tables(out);
    report.total_seconds = seconds_since(sweep_start);
    return report;
}

}  // namespace

SweepReport run_sweep(const SweepConfig& config, const std::string& output_folder, int threads, std::FILE* progress) {
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
