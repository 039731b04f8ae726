#include "toolkit/boxlod.h"

#include "base/memory_budget.h"
#include "base/parallel.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/metrics/metric_registry.h"
#include "toolkit/model/framing.h"

namespace boxlod {
namespace {

void check_threads(int threads) {
    if (!thread_count_range.contains(threads))
        throw InputError("threads: " + out_of_range_message(thread_count_range, std::to_string(threads)));
}

// The most levels a chain holds: MSFT_lod clients load the 10 finest (command_build.cpp).
constexpr int max_chain_levels = 10;

Level level_of(ChainLevel level, double switch_distance) {
    return {level.level, std::move(level.lod.model), std::move(level.lod.statistics), switch_distance};
}

// Levels first..last of the chain, each distinct one once, its budget checked before any is built.
std::vector<Level> distinct_levels(Chain& chain, int first, int last) {
    std::vector<int> asked;
    for (int c = first; c <= last; ++c) asked.push_back(c);
    check_chain_budgets(chain, asked);
    std::vector<Level> levels;
    take_distinct_levels(chain, first, last, last - first + 1,
                         [&](ChainLevel level) { levels.push_back(level_of(std::move(level), 0)); });
    return levels;
}

}  // namespace

Model read_model(const std::string& path, const std::string& city_lod, int chain_level) {
    return load_model(path, {.chain_level = chain_level, .city_lod = city_lod});
}

void write_model(const Model& model, const std::string& path) { save_model(model, path); }

Level build_level(const Model& model, const LodParameters& parameters, int level, int threads) {
    check_threads(threads);
    Chain chain(model, parameters, threads);
    if (level < 0 || level > chain.obtained_levels())
        throw InputError("level " + std::to_string(level) + " is outside the levels obtained, 0.." +
                         std::to_string(chain.obtained_levels()));
    return std::move(distinct_levels(chain, level, level).front());
}

std::vector<Level> build_chain(const Model& model, const LodParameters& parameters, double switch_error,
                               int threads) {
    check_switch_error(switch_error, "switch error");
    check_threads(threads);
    Chain chain(model, parameters, threads);
    std::vector<int> every;
    for (int c = 1; c <= chain.obtained_levels(); ++c) every.push_back(c);
    check_chain_budgets(chain, every);
    SwitchedChain switched = switched_levels(chain, switch_error, max_chain_levels);
    std::vector<Level> levels;
    for (std::size_t k = 0; k < switched.levels.size(); ++k)
        levels.push_back(level_of(std::move(switched.levels[k]), switched.switch_distances[k]));
    return levels;
}

std::vector<Level> build_levels_by_budget(const Model& model, const LodParameters& parameters, int threads) {
    if (parameters.budgets.empty()) throw InputError("budgets: none given (one level per byte budget)");
    check_threads(threads);
    Chain chain(model, parameters, threads);
    return distinct_levels(chain, 1, chain.obtained_levels());
}

Shot render_model(const Model& model, const Model& framed, const Viewpoint& view, int threads) {
    check_threads(threads);
    if (!(view.direction.squaredNorm() > 0)) throw InputError("render: the view's direction has no length");
    if (!(view.distance > 0 && view.distance <= 1e6f))
        throw InputError("render: the view's distance must be in (0, 1e6]");
    if (!image_side_range.contains(view.width) || !image_side_range.contains(view.height))
        throw InputError("render: " + std::to_string(view.width) + " x " + std::to_string(view.height) +
                         " pixels: each side must be in " + "[1, " + std::to_string(max_image_side) + "]");
    check_memory("render: " + std::to_string(view.width) + " x " + std::to_string(view.height) + " pixels",
                 render_memory(view.width, view.height));
    const LodParameters drawn;  // LoD pages state their depth; other height maps take the default parallax
    const Framing framing = model_framing(framed);
    const float distance = view.distance * framing_distance(framing, drawn.fovy);
    const Camera camera = framed_camera(framing, view.direction.normalized(), distance, drawn.fovy);
    const std::unique_ptr<DrawableModel> drawable = make_drawable_model(model, nullptr, threads);
    return render_shot(drawable->drawable.batches, drawing_settings(camera, view.mode, drawn, threads),
                       view.width, view.height);
}

Comparison compare_renders(const Shot& reference, const Shot& test, int threads) {
    check_threads(threads);
    auto same_size = [&](const Coverage& coverage) {
        return coverage.width == reference.image.width && coverage.height == reference.image.height;
    };
    if (reference.image.width != test.image.width || reference.image.height != test.image.height ||
        !same_size(reference.coverage) || !same_size(test.coverage))
        throw InputError("compare: the shots and their coverages differ in size");
    const std::vector<Metric> asked = {Metric::rmse, Metric::psnr,         Metric::ssim,
                                       Metric::flip, Metric::flip_covered, Metric::iou};
    const MetricValues v = measure_metrics(asked, {.reference = reference.image,
                                                   .test = test.image,
                                                   .reference_coverage = &reference.coverage,
                                                   .test_coverage = &test.coverage,
                                                   .threads = threads});
    return {v.values[0], v.values[1], v.values[2], v.values[3], v.values[4], v.values[5]};
}

}  // namespace boxlod
