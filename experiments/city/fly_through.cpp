#include "experiments/city/fly_through.h"

#include "base/atomic_write.h"
#include "base/csv.h"
#include "base/key_values.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "experiments/city/contact_sheet.h"
#include "toolkit/drawing/resident_drawables.h"
#include "toolkit/formats/model_bytes.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/pages/boxes.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/image_metrics.h"
#include "toolkit/metrics/metric_registry.h"
#include "toolkit/model/framing.h"
#include "toolkit/model/statistics.h"
#include "toolkit/selection/face_budget.h"
#include "toolkit/selection/strategy_text.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <regex>
#include <stdexcept>

namespace boxlod {
namespace {

namespace fs = std::filesystem;
const Eigen::Vector3f sky{0.62f, 0.75f, 0.9f};  // linear background

// One light for the whole city, high above it towards +X+Z, so that lighting does not
// change as the camera moves (light_for_camera would follow it).
Light city_light(const Bounds& bounds) {
    Light light;
    const Framing framing = framing_of(bounds);
    light.position = framing.center + Eigen::Vector3f(0.6f, 1.5f, 0.8f) * (2 * framing.radius);
    return light;
}

// The city draws in normal mode: height maps are neither read, nor packed, nor paid for.
constexpr RenderMode city_render_mode = RenderMode::normal;

RenderSettings city_render_settings(const Camera& camera, const Light& light, int threads) {
    RenderSettings settings;
    settings.camera = camera;
    settings.mode = city_render_mode;
    settings.light = light;
    settings.threads = threads;
    return settings;
}

Image8 render_batches(const std::vector<Batch>& batches, const Camera& camera, const Light& light, int width,
                      int height, int threads) {
    const RenderSettings settings = city_render_settings(camera, light, threads);
    Frame frame = make_frame(width, height, sky);
    render(batches, settings, frame);
    return frame_to_srgb8(frame);
}

// 1 - SSIM of a level against the original seen from +X+Y+Z at the level's
// sizing distance, lit by that camera's light: the same wherever the design stands.
MeasuredError measure_level_error(const Drawable& level, const Drawable& original,
                                  const SelectionObject& object, double distance,
                                  const FlyThroughOptions& options) {
    Camera camera =
        camera_at_position({1, 1, 1}, object.center, float(distance), options.fovy, object.radius);
    Light light = light_for_camera(camera);
    Image8 a = render_batches(original.batches, camera, light, options.width, options.height, 1);
    Image8 b = render_batches(level.batches, camera, light, options.width, options.height, 1);
    return {1 - ssim(a, b, 1), distance, options.fovy, double(options.height)};
}

// Measured switching: each level some distance draws switches in where the
// chain measured it to stay within `error` (chain.h: switched_levels, as
// build --chain and tiles switch); the others have no switch distance.
void set_switch_distances(Chain& chain, double error, std::vector<SelectionLevel>& levels) {
    const SwitchedChain switched = switched_levels(chain, error, int(levels.size()));
    for (std::size_t k = 0; k < switched.levels.size(); ++k)
        levels[std::size_t(switched.levels[k].level)].switch_distance = switched.switch_distances[k];
}

// A design's LoD, built by one thread. Its textures go into `cache` first, so
// that its levels share them instead of packing copies.
DesignLevels build_design(const Model& model, TextureCache& cache, const FlyThroughOptions& options,
                          bool measure_error) {
    DesignLevels built;
    decode_textures(model, &cache);
    built.bounds = model_bounds(model);
    built.levels.push_back(pack_drawable(model, &cache, maps_drawn(city_render_mode).height));
    MeshCounts original = mesh_counts(model);
    std::vector<SelectionLevel> levels = {{original.faces, std::nullopt, std::nullopt, std::nullopt}};
    built.triangles = {original.triangles};
    built.costs = {cost_parts(model)};
    LodParameters p = options.levels;
    p.fovy = options.fovy;
    p.resolution = float(options.height);
    p.distance = options.base_distance;  // level 1's; level c's doubles it (chain.h: level_distances)
    p.level_distances = {};
    Chain chain(model, p, 1);
    const auto& boxes = chain.boxes();
    for (int c = 1; c <= chain.obtained_levels(); ++c) {
        Lod lod = chain.build(c);
        MeshCounts counts = mesh_counts(lod.model);
        levels.push_back({counts.faces, chain.sizing(c), std::nullopt, std::nullopt});
        built.triangles.push_back(counts.triangles);
        built.costs.push_back(lod.cost);
        built.levels.push_back(pack_drawable(lod.model, &cache, maps_drawn(city_render_mode).height));
    }
    if (const auto* measured = std::get_if<MeasuredSwitch>(
            &options.strategy))  // where the chain measured each level within the error
        set_switch_distances(chain, measured->error, levels);
    if (boxes[0]) {
        built.object = selection_object(*boxes[0], std::move(levels));
    } else {  // no geometry at all: a point that draws nothing
        built.object.center = built.bounds.center();
        built.object.levels = std::move(levels);
    }
    if (measure_error) {
        std::unique_ptr<DrawableModel> full = unpack_drawable(built.levels[0]);
        for (int c = 1; c <= coarsest_level(built.object); ++c)
            built.object.levels[std::size_t(c)].error =
                measure_level_error(unpack_drawable(built.levels[std::size_t(c)])->drawable, full->drawable,
                                    built.object, chain.sized_parameters(c).distance, options);
    }
    return built;
}

// A design is derived under a name of its own, not its lot's: lots showing it share its content.
Model derive_design(const CityPlan& city, std::size_t design) {
    return design_model(city, design, "design_" + std::to_string(design));
}

// Which LoD each lot draws: one per distinct design content (in order of the
// lots first showing it), or one per lot without sharing. Returns the design
// each LoD is built from; `lod_of_lot` gets each lot's.
std::vector<std::size_t> lods_to_build(const CityPlan& city, bool share, int threads,
                                       std::vector<std::size_t>& lod_of_lot) {
    std::vector<std::size_t> designs;
    lod_of_lot.clear();
    if (!share) {
        for (const CityLot& lot : city.lots) {
            lod_of_lot.push_back(designs.size());
            designs.push_back(lot.design);
        }
        return designs;
    }
    std::vector<std::size_t> shown;  // the designs the lots show, once each
    std::vector<std::ptrdiff_t> index_of_design(city.designs.size(), -1);
    for (const CityLot& lot : city.lots)
        if (index_of_design[lot.design] < 0) {
            index_of_design[lot.design] = std::ptrdiff_t(shown.size());
            shown.push_back(lot.design);
        }
    std::vector<ContentDigest> digests(shown.size());
    parallel_for(shown.size(), threads, [&](std::size_t i) {
        const std::string bytes = model_bytes(derive_design(city, shown[i]));
        digests[i] = content_digest(bytes.data(), bytes.size());
    });
    std::map<ContentDigest, std::size_t> lod_of_digest;
    std::vector<std::size_t> lod_of_shown;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        auto [entry, added] = lod_of_digest.try_emplace(digests[i], designs.size());
        if (added) designs.push_back(shown[i]);
        lod_of_shown.push_back(entry->second);
    }
    for (const CityLot& lot : city.lots)
        lod_of_lot.push_back(lod_of_shown[std::size_t(index_of_design[lot.design])]);
    return designs;
}

SelectionObject moved(SelectionObject object, const Eigen::Vector3f& translation) {
    object.center += translation;
    if (object.box) object.box->center += translation;
    return object;
}

// What the frame draws: faces, triangles, cost; levels changed since `previous`.
void record_cost(const CityLevels& city, const FrameRecord* previous, FrameRecord& record) {
    record.faces = faces_drawn(city.objects, record.levels, city.street_faces);
    record.triangles = city.street_triangles;
    std::vector<const CostParts*> drawn = {&city.street_cost};
    for (std::size_t b = 0; b < city.buildings.size(); ++b) {
        const DesignLevels& design = city.designs[city.buildings[b].design];
        record.triangles += design.triangles[std::size_t(record.levels[b])];
        drawn.push_back(&design.costs[std::size_t(record.levels[b])]);
        if (previous && record.levels[b] != previous->levels[b]) ++record.levels_changed;
    }
    record.cost = drawn_cost(drawn, city_render_mode);
}

std::size_t thumbnail_factor(int width) { return std::size_t(std::max(1, (width + 239) / 240)); }

}  // namespace

CityLevels build_city_levels(const CityPlan& city, const FlyThroughOptions& options, bool measure_error,
                             std::FILE* progress) {
    auto start = Clock::now();
    CityLevels out;
    // Every level of every design copies some of the city's few grammar textures: decoded once.
    TextureCache cache;
    Model streets = city_streets(city);
    out.textures = decode_textures(streets, &cache);
    out.streets = make_drawable(streets, out.textures);
    MeshCounts street_counts = mesh_counts(streets);
    out.street_cost = cost_parts(streets);
    out.street_faces = street_counts.faces;
    out.street_triangles = street_counts.triangles;
    out.bounds = model_bounds(streets);

    std::vector<std::size_t> lod_of_lot;
    const std::vector<std::size_t> designs =
        lods_to_build(city, options.share_designs, options.threads, lod_of_lot);
    out.designs.resize(designs.size());
    parallel_for(designs.size(), options.threads, [&](std::size_t i) {
        auto design_start = Clock::now();
        out.designs[i] = build_design(derive_design(city, designs[i]), cache, options, measure_error);
        if (progress) {
            std::fprintf(progress, "boxlod city: design %zu: %d levels in %.2f s\n", designs[i],
                         coarsest_level(out.designs[i].object), seconds_since(design_start));
            std::fflush(progress);
        }
    });
    for (const DesignLevels& design : out.designs) {
        out.max_level = std::max(out.max_level, coarsest_level(design.object));
        for (const PackedDrawable& level : design.levels) {
            out.packed_bytes += packed_size(level);
            out.unpacked_bytes += level.unpacked_size;
        }
    }
    for (std::size_t i = 0; i < city.lots.size(); ++i) {
        const CityLot& lot = city.lots[i];
        const DesignLevels& design = out.designs[lod_of_lot[i]];
        out.buildings.push_back({lot.name, lod_of_lot[i], lot.center});
        out.objects.push_back(moved(design.object, lot.center));
        if (!design.bounds.empty()) {
            out.bounds.add(design.bounds.min + lot.center);
            out.bounds.add(design.bounds.max + lot.center);
        }
    }
    out.seconds = seconds_since(start);
    return out;
}

Camera pose_camera(const CameraPose& pose, const Bounds& city, float fovy_degrees) {
    Camera camera;
    camera.position = pose.eye;
    camera.target = pose.target;
    camera.fovy_degrees = fovy_degrees;
    Eigen::Vector3f look = (pose.target - pose.eye).normalized();
    if (std::abs(look.y()) > 0.999f)
        camera.up = look.y() < 0 ? Eigen::Vector3f(0, 0, -1) : Eigen::Vector3f(0, 0, 1);
    const Framing framing = framing_of(city);
    fit_depth_range(camera, (pose.eye - framing.center).norm(), framing.radius);
    return camera;
}

namespace {

const PackedDrawable& level_drawn(const CityLevels& city, std::size_t building, int level) {
    return city.designs[city.buildings[building].design].levels[std::size_t(level)];
}

// The buildings a camera sees at `levels` (a building outside the view would draw no pixel).
std::vector<std::size_t> buildings_in_view(const CityLevels& city, const std::vector<int>& levels,
                                           const Camera& camera, float aspect) {
    std::vector<std::size_t> shown;
    for (std::size_t b = 0; b < city.buildings.size(); ++b) {
        const PackedDrawable& level = level_drawn(city, b, levels[b]);
        const Eigen::Vector3f center = level.bounds.center() + city.buildings[b].translation;
        if (!level.bounds.empty() && sphere_in_view(camera, aspect, center, framing_of(level.bounds).radius))
            shown.push_back(b);
    }
    return shown;
}

void append_moved(const Drawable& drawable, const Eigen::Vector3f& translation, std::vector<Batch>& batches) {
    for (Batch batch : drawable.batches) {
        batch.translation = translation;
        batches.push_back(batch);
    }
}

// The frame with every building in view at level 0: the reference a frame is
// compared with. Unpacked apart from the frames' cache, a group of
// options.full_detail_group_bytes at a time, each group drawn over the earlier
// ones from their depth and the blended surfaces of all last (renderer.h:
// depth_from_frame): the picture of one render of them all, with at most a
// group unpacked (and the levels with blended surfaces, kept to the end).
Image8 render_full_detail(const CityLevels& city, const Camera& camera, const Light& light,
                          const FlyThroughOptions& options) {
    const float aspect = float(options.width) / float(options.height);
    const std::vector<std::size_t> shown =
        buildings_in_view(city, std::vector<int>(city.buildings.size(), 0), camera, aspect);
    RenderSettings settings = city_render_settings(camera, light, options.threads);
    settings.depth_from_frame = true;
    Frame frame = make_frame(options.width, options.height, sky);
    std::vector<std::unique_ptr<DrawableModel>> kept;  // levels with blended surfaces
    std::vector<Batch> blended;
    // Draws the opaque and masked batches; keeps the blended ones for the end.
    auto draw_opaque = [&](const std::vector<Batch>& batches) {
        std::vector<Batch> opaque;
        for (const Batch& batch : batches)
            (batch.surface.alpha_mode == AlphaMode::blend ? blended : opaque).push_back(batch);
        render(opaque, settings, frame);
    };
    draw_opaque(city.streets.batches);
    for (std::size_t first = 0; first < shown.size();) {
        std::size_t end = first, bytes = 0;
        while (end < shown.size() &&
               (end == first ||
                bytes + level_drawn(city, shown[end], 0).unpacked_size <= options.full_detail_group_bytes))
            bytes += level_drawn(city, shown[end++], 0).unpacked_size;
        std::vector<std::unique_ptr<DrawableModel>> group(end - first);
        parallel_for(group.size(), options.threads, [&](std::size_t i) {
            group[i] = unpack_drawable(level_drawn(city, shown[first + i], 0));
        });
        std::vector<Batch> batches;
        for (std::size_t i = 0; i < group.size(); ++i)
            append_moved(group[i]->drawable, city.buildings[shown[first + i]].translation, batches);
        draw_opaque(batches);
        for (std::unique_ptr<DrawableModel>& level : group)
            if (std::any_of(level->drawable.batches.begin(), level->drawable.batches.end(),
                            [](const Batch& b) { return b.surface.alpha_mode == AlphaMode::blend; }))
                kept.push_back(std::move(level));
        first = end;
    }
    if (!blended.empty()) render(blended, settings, frame);
    return frame_to_srgb8(frame);
}

// Every building's level for the view (and the face budget), each building's
// choice its own: chunks of them in parallel.
std::vector<int> select_levels(const CityLevels& city, std::vector<Selector>& selectors,
                               const Strategy& strategy, const SelectionView& view,
                               const FlyThroughOptions& options) {
    const std::size_t n = city.buildings.size();
    std::vector<int> levels(n);
    constexpr std::size_t chunk = 1024;
    parallel_for((n + chunk - 1) / chunk, options.threads, [&](std::size_t c) {
        for (std::size_t b = c * chunk; b < std::min(n, (c + 1) * chunk); ++b) {
            // Each object's levels are an allocation of their own, scattered over a
            // large city's heap: fetched a few buildings ahead, their misses overlap.
            constexpr std::size_t ahead = 8;
            if (b + ahead < n && !city.objects[b + ahead].levels.empty())
                __builtin_prefetch(&city.objects[b + ahead].levels.back());
            levels[b] = select_level(selectors[b], strategy, city.objects[b], view);
        }
    });
    if (options.face_budget) {
        std::vector<double> importance;
        for (const SelectionObject& object : city.objects)
            importance.push_back(selection_importance(strategy, object, view));
        fit_face_budget(city.objects, importance, *options.face_budget, levels, city.street_faces);
    }
    return levels;
}

// A frame's errors against the same view at full detail.
ImageErrors full_detail_errors(const CityLevels& city, const Camera& camera, const Light& light,
                               const Image8& image, const FlyThroughOptions& options) {
    Image8 full = render_full_detail(city, camera, light, options);
    MetricPair pair{full, image};
    pair.pixels_per_degree = options.pixels_per_degree;
    pair.threads = options.threads;
    std::vector<double> e = measure_metrics({Metric::psnr, Metric::ssim, Metric::flip}, pair).values;
    return {e[0], e[1], e[2]};
}

}  // namespace

std::vector<FrameRecord> fly_through(const CityLevels& city, const std::vector<CameraPose>& path,
                                     const FlyThroughOptions& options, const FrameDone& frame_done) {
    std::vector<Selector> selectors(city.buildings.size(), Selector{options.hysteresis, -1});
    std::vector<FrameRecord> records;
    const Strategy strategy = scale_detail(options.strategy, options.detail);
    Light light = city_light(city.bounds);
    ResidentDrawables resident(options.memory_budget);
    // The streets and every building in view at its level, unpacked where needed.
    auto batches_for = [&](const std::vector<int>& levels, const Camera& camera, FrameRecord& record) {
        const ScopedTimer timer(record.unpack_seconds);
        std::size_t unpacked_before = resident.counts().unpacked;
        const std::vector<std::size_t> shown =
            buildings_in_view(city, levels, camera, float(options.width) / float(options.height));
        std::vector<const PackedDrawable*> wanted;
        for (std::size_t b : shown) wanted.push_back(&level_drawn(city, b, levels[b]));
        std::vector<Batch> batches = city.streets.batches;
        std::vector<const Drawable*> drawables = resident.acquire(wanted, options.threads);
        for (std::size_t i = 0; i < shown.size(); ++i)
            append_moved(*drawables[i], city.buildings[shown[i]].translation, batches);
        record.levels_unpacked += resident.counts().unpacked - unpacked_before;
        record.resident_bytes = resident.counts().resident_bytes;
        return batches;
    };
    for (std::size_t k = 0; k < path.size(); ++k) {
        FrameRecord record;
        const SelectionView view{pose_camera(path[k], city.bounds, options.fovy), options.width,
                                 options.height};
        {
            const ScopedTimer timer(record.select_seconds);
            record.levels = select_levels(city, selectors, strategy, view, options);
        }
        record_cost(city, k > 0 ? &records.back() : nullptr, record);
        const std::vector<Batch> batches = batches_for(record.levels, view.camera, record);
        Image8 image;
        {
            const ScopedTimer timer(record.render_seconds);
            image =
                render_batches(batches, view.camera, light, options.width, options.height, options.threads);
        }
        if (options.error_every > 0 && k % std::size_t(options.error_every) == 0) {
            const ScopedTimer timer(record.error_seconds);
            record.error = full_detail_errors(city, view.camera, light, image, options);
        }
        if (frame_done) frame_done(int(k), image, record);
        records.push_back(std::move(record));
    }
    return records;
}

std::string frames_csv(const std::vector<FlyThroughRun>& runs, const CityLevels& city,
                       const Strategy& strategy) {
    std::vector<std::string> header = {
        "frame",         "strategy",          "detail", "faces",    "triangles", "draw_calls", "mesh_bytes",
        "texture_bytes", "texture_bytes_gpu", "bytes",  "buildings"};
    for (int c = 0; c <= city.max_level; ++c) header.push_back("level_" + std::to_string(c));
    for (const char* column : {"levels_changed", "psnr", "ssim", "flip"}) header.push_back(column);
    std::string text = csv_row(header) + "\n";
    const std::string name = format_strategy(strategy);
    for (const FlyThroughRun& run : runs)
        for (std::size_t k = 0; k < run.frames.size(); ++k) {
            const FrameRecord& f = run.frames[k];
            std::vector<std::size_t> histogram(std::size_t(city.max_level) + 1, 0);
            for (int level : f.levels) ++histogram[std::size_t(level)];
            std::vector<std::string> fields = {std::to_string(k),
                                               name,
                                               format_number(run.detail),
                                               std::to_string(f.faces),
                                               std::to_string(f.triangles),
                                               std::to_string(f.cost.draw_calls),
                                               std::to_string(f.cost.mesh_bytes),
                                               std::to_string(f.cost.texture_bytes),
                                               std::to_string(f.cost.texture_bytes_gpu),
                                               std::to_string(f.cost.bytes()),
                                               std::to_string(f.levels.size())};
            for (std::size_t count : histogram) fields.push_back(std::to_string(count));
            fields.push_back(std::to_string(f.levels_changed));
            for (double value :
                 {f.error ? f.error->psnr : 0, f.error ? f.error->ssim : 0, f.error ? f.error->flip : 0})
                fields.push_back(f.error ? format_number(value) : "");
            text += csv_row(fields) + "\n";
        }
    return text;
}

std::string timings_csv(const std::vector<FlyThroughRun>& runs) {
    std::string text =
        "frame,detail,select_seconds,unpack_seconds,render_seconds,levels_unpacked,resident_bytes\n";
    for (const FlyThroughRun& run : runs)
        for (std::size_t k = 0; k < run.frames.size(); ++k) {
            const FrameRecord& f = run.frames[k];
            text += csv_row({std::to_string(k), format_number(run.detail), format_number(f.select_seconds),
                             format_number(f.unpack_seconds), format_number(f.render_seconds),
                             std::to_string(f.levels_unpacked), std::to_string(f.resident_bytes)}) +
                    "\n";
        }
    return text;
}

namespace {

FlyThroughReport summarize(const std::vector<FrameRecord>& frames, const CityLevels& levels, double detail) {
    FlyThroughReport report;
    report.detail = detail;
    report.frames = frames.size();
    report.buildings = levels.buildings.size();
    report.lods_built = levels.designs.size();
    report.level_totals.assign(std::size_t(levels.max_level) + 1, 0);
    report.faces_min = frames.empty() ? 0 : std::numeric_limits<std::size_t>::max();
    double faces = 0, psnr_sum = 0, ssim_sum = 0, flip_sum = 0;
    std::size_t finite_psnr = 0;
    for (const FrameRecord& f : frames) {
        faces += double(f.faces);
        report.faces_min = std::min(report.faces_min, f.faces);
        report.faces_max = std::max(report.faces_max, f.faces);
        for (int level : f.levels) ++report.level_totals[std::size_t(level)];
        report.levels_changed += f.levels_changed;
        report.select_seconds += f.select_seconds;
        report.unpack_seconds += f.unpack_seconds;
        report.levels_unpacked += f.levels_unpacked;
        report.resident_peak_bytes = std::max(report.resident_peak_bytes, f.resident_bytes);
        report.render_seconds += f.render_seconds;
        report.error_seconds += f.error_seconds;
        if (!f.error) continue;
        ++report.sampled_frames;
        if (std::isfinite(f.error->psnr)) {
            psnr_sum += f.error->psnr;
            ++finite_psnr;
        }
        ssim_sum += f.error->ssim;
        flip_sum += f.error->flip;
    }
    if (!frames.empty()) report.faces_mean = faces / double(frames.size());
    if (report.sampled_frames) {
        report.psnr_mean =
            finite_psnr ? psnr_sum / double(finite_psnr) : std::numeric_limits<double>::infinity();
        report.ssim_mean = ssim_sum / double(report.sampled_frames);
        report.flip_mean = flip_sum / double(report.sampled_frames);
    }
    return report;
}

}  // namespace

bool is_fly_through_file(const std::string& name) {
    static const std::regex file(
        R"((frames|timings)\.csv|(detail_[0-9.e+-]+/?)?(frames|frames/frame_\d+\.png|contact_sheet\.png)?)");
    return !name.empty() && std::regex_match(name, file);
}

double fly_through_memory(const CityPlan& city, const FlyThroughOptions& options) {
    const std::size_t lods =
        options.share_designs ? std::min(city.designs.size(), city.lots.size()) : city.lots.size();
    // Per distinct building its packed levels and per lot its placement, as the
    // measured peaks give them (docs/city.md: Scale); a compared frame's
    // originals a group at a time, with its render.
    return 0.3e6 * double(lods) + 0.1e6 * double(city.lots.size()) +
           1.5 * double(options.full_detail_group_bytes) + render_memory(options.width, options.height) +
           (options.error_every > 0 ? metrics_memory(options.width, options.height) : 0);
}

bool needs_measured_errors(const Strategy& strategy) {
    const auto* texel = std::get_if<TexelExact>(&strategy);
    return texel && texel->error_budget;
}

std::vector<FlyThroughReport> run_fly_through(const CityLevels& levels, const std::vector<CameraPose>& path,
                                              const FlyThroughOptions& options,
                                              const std::vector<double>& details,
                                              const std::string& output_folder, std::FILE* progress) {
    if (details.empty()) throw std::invalid_argument("run_fly_through: no detail to run");

    fs::path folder(output_folder);
    std::vector<FlyThroughRun> runs;
    std::vector<FlyThroughReport> reports;
    for (double detail : details) {
        auto start = Clock::now();
        fs::path run_folder = details.size() == 1 ? folder : folder / ("detail_" + format_number(detail));
        fs::path frames_folder = run_folder / "frames";
        fs::create_directories(frames_folder);
        // Up to 16 frames for the contact sheet, spread evenly over the path.
        const std::size_t count = path.size(), shown = std::min<std::size_t>(16, count);
        std::vector<std::size_t> sheet_frames;
        for (std::size_t i = 0; i < shown; ++i) sheet_frames.push_back(i * count / shown);
        std::vector<Image8> thumbnails;
        std::vector<std::string> labels;
        std::size_t next_progress = 0;
        auto frame_done = [&](int k, const Image8& image, const FrameRecord& record) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%04d.png", k);
            write_png((frames_folder / name).string(), image);
            if (std::find(sheet_frames.begin(), sheet_frames.end(), std::size_t(k)) != sheet_frames.end()) {
                thumbnails.push_back(shrink(image, int(thumbnail_factor(image.width))));
                labels.push_back("frame " + std::to_string(k) + ": " + std::to_string(record.faces) +
                                 " faces");
            }
            if (progress && std::size_t(k) + 1 >= next_progress) {
                std::fprintf(progress, "boxlod city: detail %s: frame %d/%zu: %zu faces\n",
                             format_number(detail).c_str(), k + 1, count, record.faces);
                std::fflush(progress);
                next_progress = std::size_t(k) + 1 + std::max<std::size_t>(1, count / 10);
            }
        };
        FlyThroughOptions run_options = options;
        run_options.detail = detail;
        runs.push_back({detail, fly_through(levels, path, run_options, frame_done)});
        write_png((run_folder / "contact_sheet.png").string(), contact_sheet(thumbnails, labels, 4));
        FlyThroughReport report = summarize(runs.back().frames, levels, detail);
        report.build_seconds = levels.seconds;
        report.packed_bytes = levels.packed_bytes;
        report.unpacked_bytes = levels.unpacked_bytes;
        report.total_seconds = seconds_since(start);
        reports.push_back(std::move(report));
    }
    write_text_atomically((folder / "frames.csv").string(), frames_csv(runs, levels, options.strategy));
    write_text_atomically((folder / "timings.csv").string(), timings_csv(runs));
    return reports;
}

}  // namespace boxlod
