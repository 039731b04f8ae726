#include "experiments/sweep/sweep_group.h"

#include "base/csv.h"
#include "base/key_values.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "experiments/sweep/sweep_shots.h"
#include "toolkit/metrics/heatmap.h"
#include "toolkit/model/statistics.h"

#include <algorithm>
#include <sstream>

namespace boxlod {

// `cost`: the model's, when its builder has it already (an LoD); else computed here.
SweepCandidate candidate(Model model, Atlas atlas, std::size_t nodes_with_box, int obtained_levels,
                         const CostParts* cost) {
    SweepCandidate c;
    c.cost = cost ? *cost : cost_parts(model);
    c.model = std::move(model);
    c.atlas = std::move(atlas);
    c.nodes_with_box = nodes_with_box;
    c.obtained_levels = obtained_levels;
    return c;
}

std::size_t rows_per_group(const SweepConfig& config) {
    return config.views.size() * config.distances.size() * config.render_modes.size();
}

namespace {

// A row key (CSV text already) extended by more fields.
std::string extend_row(const std::string& key, const std::vector<std::string>& more) {
    return key + "," + csv_row(more);
}

std::string eta_text(double seconds) {
    int s = int(seconds + 0.5);
    std::ostringstream out;
    if (s >= 3600) out << s / 3600 << "h";
    if (s >= 60) out << s / 60 % 60 << "m";
    out << s % 60 << "s";
    return out.str();
}

// The results.csv fields of a row after its key.
std::vector<std::string> result_fields(const SweepCandidate& c, RenderMode mode, const Shot& original,
                                       const Metrics& metrics) {
    const ModelCost cost = drawn_cost({&c.cost}, mode);
    MeshCounts counts = mesh_counts(c.model);
    int largest_page = 0;
    for (const Eigen::Vector2i& page : c.atlas.pages)
        largest_page = std::max({largest_page, page.x(), page.y()});
    std::vector<std::string> fields = {std::to_string(c.obtained_levels),
                                       std::to_string(counts.faces),
                                       std::to_string(counts.triangles),
                                       std::to_string(counts.vertices),
                                       std::to_string(counts.batches),
                                       std::to_string(page_texels(c.atlas)),
                                       std::to_string(c.face_texels),
                                       std::to_string(c.atlas.pages.size()),
                                       std::to_string(largest_page),
                                       std::to_string(c.nodes_with_box),
                                       c.depth_error,
                                       c.measured_error,
                                       std::to_string(cost.draw_calls),
                                       std::to_string(cost.mesh_bytes),
                                       std::to_string(cost.texture_bytes),
                                       std::to_string(cost.texture_bytes_gpu),
                                       std::to_string(cost.bytes()),
                                       std::to_string(covered_pixels(original.coverage)),
                                       c.variant};
    fields.insert(fields.end(), metrics.values.begin(), metrics.values.end());
    return fields;
}

// A row of a group, not yet in results.csv.
struct MissingRow {
    std::size_t view, distance;
    RenderMode mode;
    std::string key;
};

// The group's rows in the sweep's order (noted in `out.order`); those
// results.csv holds already are counted as skipped, the others returned.
std::vector<MissingRow> missing_rows(ModelRun& run, SweepOutput& out, SweepReport& report,
                                     const std::string& group) {
    const SweepConfig& config = run.config;
    std::vector<MissingRow> missing;
    for (std::size_t v = 0; v < config.views.size(); ++v)
        for (std::size_t d = 0; d < config.distances.size(); ++d)
            for (RenderMode mode : config.render_modes) {
                std::string key = extend_row(
                    group, {config.views[v], format_number(config.distances[d]), render_mode_name(mode)});
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
void make_reference_shots(ModelRun& run, SweepOutput& out, SweepReport& report,
                          const std::vector<MissingRow>& rows) {
    const SweepConfig& config = run.config;
    std::vector<std::tuple<std::size_t, std::size_t, RenderMode>> keys;
    for (const MissingRow& row : rows) {
        auto key = std::make_tuple(row.view, row.distance, row.mode);
        if (!run.references.count(key) && std::find(keys.begin(), keys.end(), key) == keys.end())
            keys.push_back(key);
    }
    if (keys.empty()) return;
    if (!run.original) run.original = make_drawable_model(run.model);
    const bool flip_measured =
        std::find(config.metrics.begin(), config.metrics.end(), Metric::flip) != config.metrics.end();
    std::vector<Shot> shots(keys.size());
    std::vector<double> render_seconds(keys.size(), 0), metric_seconds(keys.size(), 0);
    parallel_for(keys.size(), run.threads, [&](std::size_t k) {
        const auto [v, d, mode] = keys[k];
        const RenderSettings settings =
            view_settings(run.framing, config.views[v], config.distances[d], mode, config.lod, 1);
        shots[k] = timed(render_seconds[k], [&] {
            return render_shot(run.original->drawable.batches, settings, config.width, config.height,
                               config.supersampling);
        });
        if (flip_measured)
            shots[k].flip_reference = timed(metric_seconds[k], [&] {
                return prepare_flip_reference(shots[k].image, config.pixels_per_degree, 1);
            });
    });
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const auto [v, d, mode] = keys[k];
        report.render_seconds += render_seconds[k];
        report.metric_seconds += metric_seconds[k];
        ++report.original_renders;
        if (out.keep_images)
            save_image(out,
                       csv_row({run.entry.name, "original", config.views[v],
                                format_number(config.distances[d]), render_mode_name(mode)}),
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
DrawnRow draw_row(const ModelRun& run, bool keep_image, const SweepCandidate& c, const MissingRow& row) {
    const SweepConfig& config = run.config;
    const Shot& original_shot = run.references.at({row.view, row.distance, row.mode});
    const RenderSettings settings = view_settings(run.framing, config.views[row.view],
                                                  config.distances[row.distance], row.mode, config.lod, 1);
    DrawnRow drawn;
    Shot shot = timed(drawn.render_seconds, [&] {
        return render_shot(c.drawable->drawable.batches, settings, config.width, config.height,
                           config.supersampling);
    });
    Metrics metrics = timed(drawn.metric_seconds, [&] {
        return compare_shots(config, original_shot, shot, config.keep_images == KeptImages::all, 1);
    });
    drawn.result = extend_row(row.key, result_fields(c, row.mode, original_shot, metrics));
    drawn.timing = extend_row(row.key, {format_number(c.seconds), format_number(drawn.render_seconds),
                                        format_number(drawn.metric_seconds)});
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
                                const std::vector<const SweepCandidate*>& candidates,
                                const std::vector<MissingRow>& rows) {
    make_reference_shots(run, out, report, rows);
    std::vector<DrawnRow> drawn(rows.size());
    parallel_for(rows.size(), run.threads,
                 [&](std::size_t r) { drawn[r] = draw_row(run, out.keep_images, *candidates[r], rows[r]); });
    for (const DrawnRow& row : drawn) {
        report.render_seconds += row.render_seconds;
        report.metric_seconds += row.metric_seconds;
    }
    report.lod_renders += rows.size();
    return drawn;
}

// The group's line on the progress stream, with the model's ETA.
void report_group(const ModelRun& run, const std::string& group, std::size_t rows, double seconds) {
    if (!run.progress) return;
    const double eta = run.seconds / double(run.computed) * double(run.rows - run.done);
    std::fprintf(run.progress,
                 "boxlod sweep: model %zu/%zu %s: %zu rows in %.2f s; %zu/%zu rows of this model, ETA %s\n",
                 run.index + 1, run.config.models.size(), group.c_str(), rows, seconds, run.done, run.rows,
                 eta_text(eta).c_str());
    std::fflush(run.progress);
}

}  // namespace

void run_group(ModelRun& run, SweepOutput& out, SweepReport& report, const std::string& group,
               const std::function<int(RenderMode, std::size_t, std::size_t)>& slot,
               const std::function<SweepCandidate(int, int)>& make, int alternatives, double budget) {
    auto group_start = Clock::now();
    const std::vector<MissingRow> missing = missing_rows(run, out, report, group);
    if (missing.empty()) return;
    std::vector<std::vector<DrawnRow>> drawn(static_cast<std::size_t>(alternatives));
    std::vector<double> mean_error(std::size_t(alternatives), 0);
    std::vector<char> fits(std::size_t(alternatives), true);
    for (int a = 0; a < alternatives; ++a) {
        std::map<int, SweepCandidate> candidates;
        std::vector<const SweepCandidate*> of_row;
        for (const MissingRow& row : missing) {
            int s = slot(row.mode, row.view, row.distance);
            auto found = candidates.find(s);
            if (found == candidates.end()) {
                double seconds = 0;
                SweepCandidate made = timed(seconds, [&] {
                    SweepCandidate built = make(s, a);
                    if (!built.drawable) built.drawable = make_drawable_model(built.model);
                    return built;
                });
                made.seconds = seconds;
                report.build_seconds += seconds;
                ++report.lods_built;
                found = candidates.emplace(s, std::move(made)).first;
            }
            of_row.push_back(&found->second);
            if (budget >= 0 && double(combined_cost({&found->second.cost}).bytes()) > budget)
                fits[std::size_t(a)] = false;
        }
        drawn[std::size_t(a)] = draw_rows(run, out, report, of_row, missing);
        for (const DrawnRow& row : drawn[std::size_t(a)])
            mean_error[std::size_t(a)] += row.error / double(missing.size());
    }
    const bool any_fits = std::find(fits.begin(), fits.end(), true) != fits.end();
    std::size_t best =
        fits.size();  // the first of the lowest error among those within the budget, or all where none is
    for (std::size_t a = 0; a < fits.size(); ++a)
        if ((fits[a] || !any_fits) && (best == fits.size() || mean_error[a] < mean_error[best])) best = a;
    for (std::size_t r = 0; r < missing.size(); ++r) {
        DrawnRow& row = drawn[best][r];
        out.results.rows[missing[r].key] = row.result;
        out.timings.rows[missing[r].key] = row.timing;
        if (out.keep_images) save_image(out, missing[r].key, row.image);
        if (run.config.keep_images == KeptImages::all)
            save_image(out, missing[r].key + "_heatmap", error_heatmap(row.heatmap));
    }
    write_tables(out);
    report.rows_computed += missing.size();
    run.done += missing.size();
    run.computed += missing.size();
    const double group_seconds = seconds_since(group_start);
    run.seconds += group_seconds;
    report_group(run, group, missing.size(), group_seconds);
}

}  // namespace boxlod
