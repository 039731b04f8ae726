#include "experiments/sweep.h"

#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "experiments/flip.h"
#include "experiments/heatmap.h"
#include "experiments/image_metrics.h"
#include "experiments/silhouette.h"
#include "renderer/atomic_write.h"
#include "renderer/input_error.h"
#include "toolkit/drawable.h"
#include "toolkit/key_values.h"
#include "toolkit/lod_builder.h"
#include "toolkit/model_io.h"
#include "toolkit/statistics.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace boxlod {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const std::vector<std::string> key_columns = {"model", "level_mode", "box_kind", "interpolation",
                                              "level", "view", "distance", "render_mode"};

std::string join(const std::vector<std::string>& fields) {
    std::string out;
    for (const std::string& field : fields) out += (out.empty() ? "" : ",") + field;
    return out;
}

// A CSV whose rows are found by their key columns (the first ones).
struct KeyedTable {
    std::string path, header;
    std::map<std::string, std::string> rows;  // key -> the whole line
    std::vector<std::string> file_order;      // keys as they were in the file
};

KeyedTable open_table(const std::string& path, const std::vector<std::string>& columns) {
    KeyedTable table{path, join(columns), {}, {}};
    std::ifstream in(path, std::ios::binary);
    if (!in) return table;
    std::string line;
    if (std::getline(in, line) && line != table.header)
        throw_input_error(path, "", "its columns differ from this sweep's (" + table.header + "); use another output folder");
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        std::size_t end = 0;
        for (std::size_t k = 0; k < key_columns.size() && end != std::string::npos; ++k) end = line.find(',', end + (k > 0));
        if (end == std::string::npos) throw_input_error(path, "line " + std::to_string(number), "a row with too few columns");
        std::string key = line.substr(0, end);
        if (table.rows.emplace(key, line).second) table.file_order.push_back(key);
    }
    return table;
}

// The rows in the sweep's order, then any the file had that this sweep does not make.
void write_table(const KeyedTable& table, const std::vector<std::string>& order) {
    std::string text = table.header + "\n";
    std::set<std::string> written;
    auto add = [&](const std::string& key) {
        auto row = table.rows.find(key);
        if (row != table.rows.end() && written.insert(key).second) text += row->second + "\n";
    };
    for (const std::string& key : order) add(key);
    for (const std::string& key : table.file_order) add(key);
    write_text_atomically(table.path, text);
}

Model load_sweep_model(const SweepModel& model) {
    if (!model.sample.empty()) return generate_building(sample_grammar(model.sample), BuildingOptions{});
    return load_model(model.path);
}

// A render as the metrics need it.
struct Shot {
    Image8 image;
    Coverage coverage;
};

Shot render_shot(const std::vector<Batch>& batches, const RenderSettings& settings, int width, int height) {
    Frame frame = make_frame(width, height, {1, 1, 1});
    render(batches, settings, frame);
    return {frame_to_srgb8(frame), coverage_from_mask(coverage_mask(frame))};
}

// The manual's camera positions around the model's bounding box centre (as `boxlod render --camera`).
struct ModelFraming {
    Bounds bounds;
    float radius = 1, framing_distance = 1;
};

RenderSettings view_settings(const ModelFraming& framing, const std::string& view, float multiple, RenderMode mode,
                             float fovy, int threads) {
    RenderSettings settings;
    settings.camera = camera_at_position(*camera_direction(view), framing.bounds.center(),
                                         multiple * framing.framing_distance, fovy, framing.radius);
    settings.mode = mode;
    settings.light = light_for_camera(settings.camera);
    settings.threads = threads;
    return settings;
}

struct Metrics {
    std::vector<std::string> values;  // in the config's metric order
    Plane heatmap;                    // FLIP's error when computed, else the RGB error
};

Metrics compare_shots(const SweepConfig& config, const Shot& reference, const Shot& test, bool want_heatmap, int threads) {
    Metrics out;
    std::optional<double> error;
    std::optional<FlipResult> flipped;
    for (const std::string& metric : config.metrics) {
        double value = 0;
        if (metric == "rmse" || metric == "psnr") {
            if (!error) error = rmse(reference.image, test.image);
            value = metric == "rmse" ? *error : psnr_from_rmse(*error);
        } else if (metric == "ssim") {
            value = ssim(reference.image, test.image, threads);
        } else if (metric == "flip") {
            flipped = flip(reference.image, test.image, config.pixels_per_degree, threads);
            value = flipped->mean;
        } else {
            value = silhouette_iou(reference.coverage, test.coverage);
        }
        out.values.push_back(format_number(value));  // psnr of identical images: inf
    }
    if (want_heatmap) out.heatmap = flipped ? std::move(flipped->error) : rgb_error_map(reference.image, test.image);
    return out;
}

// File names: the key's words joined by '_', anything but [A-Za-z0-9+-.] replaced.
std::string file_name(std::string name) {
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.' && c != '_') c = '_';
    return name + ".png";
}

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
    std::vector<std::string> columns = key_columns;
    for (const char* c : {"obtained_levels", "faces", "triangles", "vertices", "batches", "texels", "pages", "page_size",
                          "nodes_with_box"})
        columns.push_back(c);
    columns.insert(columns.end(), config.metrics.begin(), config.metrics.end());
    return columns;
}

std::vector<std::string> timing_columns() {
    std::vector<std::string> columns = key_columns;
    for (const char* c : {"build_seconds", "render_seconds", "metric_seconds"}) columns.push_back(c);
    return columns;
}

SweepReport run_sweep(const SweepConfig& config, const std::string& output_folder, int threads, std::FILE* progress) {
    auto sweep_start = Clock::now();
    if (threads < 0) threads = config.threads;
    SweepReport report;
    fs::create_directories(output_folder);
    fs::path images = fs::path(output_folder) / "images";
    if (config.keep_images != KeptImages::none) fs::create_directories(images);
    KeyedTable results = open_table((fs::path(output_folder) / "results.csv").string(), result_columns(config));
    KeyedTable timings = open_table((fs::path(output_folder) / "timings.csv").string(), timing_columns());
    std::vector<std::string> order;  // every key of the cross product so far, in order
    auto save_image = [&](const std::string& name, const Image8& image) {
        write_png((images / file_name(name)).string(), image);
    };

    for (std::size_t m = 0; m < config.models.size(); ++m) {
        const SweepModel& entry = config.models[m];
        Model model = load_sweep_model(entry);
        ModelFraming framing;
        framing.bounds = model_bounds(model);
        framing.radius = std::max(framing.bounds.size().norm() / 2, 1e-6f);
        framing.framing_distance = framing_distance(framing.radius, config.fovy);

        // Boxes once per box kind; the levels of every variant up front, for the row count and the ETA.
        auto start = Clock::now();
        std::map<BoxKind, std::vector<std::optional<OrientedBox>>> boxes;
        for (BoxKind kind : config.box_kinds) boxes[kind] = node_boxes(model, kind, threads);
        report.boxes_seconds += seconds_since(start);
        std::vector<Variant> variants;
        std::size_t model_rows = 0, per_level = config.views.size() * config.distances.size() * config.render_modes.size();
        for (LevelMode mode : config.level_modes)
            for (BoxKind kind : config.box_kinds)
                for (Interpolation interpolation : config.interpolations) {
                    int obtained = compute_level_values(model, mode, config.wanted_levels, interpolation, boxes[kind]).obtained_levels;
                    Variant variant{mode, kind, interpolation, obtained, {}};
                    for (int level = 0; level <= obtained; ++level)
                        if (config.levels.empty() || std::binary_search(config.levels.begin(), config.levels.end(), level))
                            variant.levels.push_back(level);
                    model_rows += variant.levels.size() * per_level;
                    variants.push_back(std::move(variant));
                }
        report.rows += model_rows;

        std::unique_ptr<DrawableModel> original;
        std::map<std::tuple<std::size_t, std::size_t, RenderMode>, Shot> references;  // per view, distance, mode
        auto reference = [&](std::size_t v, std::size_t d, RenderMode mode) -> const Shot& {
            auto key = std::make_tuple(v, d, mode);
            auto found = references.find(key);
            if (found != references.end()) return found->second;
            if (!original) original = make_drawable_model(model);
            auto render_start = Clock::now();
            RenderSettings settings = view_settings(framing, config.views[v], config.distances[d], mode, config.fovy, threads);
            Shot shot = render_shot(original->drawable.batches, settings, config.width, config.height);
            report.render_seconds += seconds_since(render_start);
            ++report.original_renders;
            if (config.keep_images != KeptImages::none)
                save_image(join({entry.name, "original", config.views[v], format_number(config.distances[d]),
                                 render_mode_name(mode)}),
                           shot.image);
            return references.emplace(key, std::move(shot)).first->second;
        };

        std::size_t model_done = 0, model_computed = 0;
        double model_seconds = 0;
        for (const Variant& variant : variants) {
            LodParameters parameters;
            parameters.level_mode = variant.mode;
            parameters.box_kind = variant.box;
            parameters.interpolation = variant.interpolation;
            parameters.wanted_levels = config.wanted_levels;
            parameters.fovy = config.fovy;
            parameters.distance = *std::min_element(config.distances.begin(), config.distances.end()) * framing.framing_distance;
            parameters.resolution = config.resolution;
            // Normal, parallax, pom and albedo draw the same baked boxes; untextured boxes are not baked.
            std::unique_ptr<LodSession> sessions[2];  // [0] textured, [1] untextured
            for (int level : variant.levels) {
                auto group_start = Clock::now();
                std::string group = join({entry.name, level_mode_name(variant.mode), box_kind_name(variant.box),
                                          interpolation_name(variant.interpolation), std::to_string(level)});
                struct Row { std::size_t view, distance; RenderMode mode; std::string key; };
                std::vector<Row> missing;
                for (std::size_t v = 0; v < config.views.size(); ++v)
                    for (std::size_t d = 0; d < config.distances.size(); ++d)
                        for (RenderMode mode : config.render_modes) {
                            std::string key = join({group, config.views[v], format_number(config.distances[d]), render_mode_name(mode)});
                            order.push_back(key);
                            if (!results.rows.count(key)) missing.push_back({v, d, mode, key});
                        }
                report.rows_skipped += per_level - missing.size();
                model_done += per_level - missing.size();
                if (missing.empty()) continue;

                struct Built { Lod lod; std::unique_ptr<DrawableModel> drawable; double seconds = 0; };
                std::optional<Built> built[2];
                auto lod_for = [&](RenderMode mode) -> Built& {
                    int kind = mode == RenderMode::untextured ? 1 : 0;
                    if (built[kind]) return *built[kind];
                    auto build_start = Clock::now();
                    if (!sessions[kind]) {
                        LodParameters p = parameters;
                        p.render_mode = kind == 1 ? RenderMode::untextured : RenderMode::normal;
                        sessions[kind] = start_lod(model, p, threads, &boxes[variant.box]);
                    }
                    Lod lod = build_lod(*sessions[kind], level, threads);
                    auto drawable = make_drawable_model(lod.model);
                    double seconds = seconds_since(build_start);
                    report.build_seconds += seconds;
                    ++report.lods_built;
                    return built[kind].emplace(Built{std::move(lod), std::move(drawable), seconds});
                };
                for (const Row& row : missing) {
                    Built& b = lod_for(row.mode);
                    const Shot& original_shot = reference(row.view, row.distance, row.mode);
                    auto render_start = Clock::now();
                    RenderSettings settings = view_settings(framing, config.views[row.view], config.distances[row.distance],
                                                            row.mode, config.fovy, threads);
                    Shot shot = render_shot(b.drawable->drawable.batches, settings, config.width, config.height);
                    double render_seconds = seconds_since(render_start);
                    report.render_seconds += render_seconds;
                    ++report.lod_renders;
                    auto metric_start = Clock::now();
                    bool heatmap = config.keep_images == KeptImages::all;
                    Metrics metrics = compare_shots(config, original_shot, shot, heatmap, threads);
                    double metric_seconds = seconds_since(metric_start);
                    report.metric_seconds += metric_seconds;

                    MeshCounts counts = mesh_counts(b.lod.model);
                    const Atlas& atlas = b.lod.atlas;
                    std::vector<std::string> fields = {
                        row.key, std::to_string(variant.obtained_levels),
                        std::to_string(counts.faces), std::to_string(counts.triangles), std::to_string(counts.vertices),
                        std::to_string(counts.batches),
                        std::to_string(std::uint64_t(atlas.pages) * std::uint64_t(atlas.page_size) * std::uint64_t(atlas.page_size)),
                        std::to_string(atlas.pages), std::to_string(atlas.pages ? atlas.page_size : 0),
                        std::to_string(b.lod.cut.box_nodes.size())};
                    fields.insert(fields.end(), metrics.values.begin(), metrics.values.end());
                    results.rows[row.key] = join(fields);
                    timings.rows[row.key] = join({row.key, format_number(b.seconds), format_number(render_seconds),
                                                  format_number(metric_seconds)});
                    if (config.keep_images != KeptImages::none) save_image(row.key, shot.image);
                    if (heatmap) save_image(row.key + "_heatmap", error_heatmap(metrics.heatmap));
                }
                write_table(results, order);
                write_table(timings, order);
                report.rows_computed += missing.size();
                model_done += missing.size();
                model_computed += missing.size();
                double group_seconds = seconds_since(group_start);
                model_seconds += group_seconds;
                if (progress) {
                    double eta = model_seconds / double(model_computed) * double(model_rows - model_done);
                    std::fprintf(progress, "boxlod sweep: model %zu/%zu %s: %zu rows in %.2f s; %zu/%zu rows of this model, ETA %s\n",
                                 m + 1, config.models.size(), group.c_str(), missing.size(), group_seconds, model_done,
                                 model_rows, eta_text(eta).c_str());
                    std::fflush(progress);
                }
            }
        }
    }
    write_table(results, order);
    write_table(timings, order);
    report.total_seconds = seconds_since(sweep_start);
    return report;
}

}  // namespace boxlod
