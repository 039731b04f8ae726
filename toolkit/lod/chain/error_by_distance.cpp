#include "toolkit/lod/chain/error_by_distance.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "base/parallel.h"
#include "renderer/renderer.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/shot.h"
#include "toolkit/model/framing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace boxlod {
namespace {

// Raised diagonals: every side of a building and its roof, none straight on.
const Eigen::Vector3f measured_directions[] = {{1, 1, 1}, {-1, 1, 1}, {-1, 1, -1}, {1, 1, -1}};
constexpr std::size_t direction_count = std::size(measured_directions);
constexpr int max_distances = 64;

// A view of `drawable` as the chain draws it (its render mode and parallax), one thread: views are measured
// side by side.
Shot render_view(const Drawable& drawable, const Camera& camera, const LodParameters& drawn, int pixels,
                 int supersampling) {
    return render_shot(drawable.batches, drawing_settings(camera, drawn.render_mode, drawn, 1), pixels,
                       pixels, supersampling);
}

}  // namespace

void check_switch_error(double error, const std::string& what) {
    if (!(error == 0 || (error >= switch_error_range.min && error <= switch_error_range.max)))
        throw InputError(what + ": " + format_number(error) + " is neither 0 nor in " +
                         range_text(switch_error_range));
}

std::vector<double> measured_distances(const Model& original, const TextureSizing& screen) {
    const Framing framing = model_framing(original);
    const double first = framing_distance(framing, screen.fovy_degrees);
    const double tangent = std::tan(double(screen.fovy_degrees) * M_PI / 360);
    // The sphere spans 2 r / (2 d tan(fovy / 2)) of the screen's height.
    const double last = double(screen.resolution) * framing.radius / (few_pixels * tangent);
    std::vector<double> distances{first};
    while (distances.back() < last && int(distances.size()) < max_distances)
        distances.push_back(first * std::exp2(0.5 * double(distances.size())));
    return distances;
}

ErrorByDistance measure_error_by_distance(const Model& original, const std::vector<const Model*>& levels,
                                          const TextureSizing& screen, const LodParameters& drawn,
                                          int threads) {
    ErrorByDistance measured;
    measured.distances = measured_distances(original, screen);
    const Framing framing = model_framing(original);
    const double tangent = std::tan(double(screen.fovy_degrees) * M_PI / 360);
    const auto reference = make_drawable_model(original, nullptr, threads);
    std::vector<std::unique_ptr<DrawableModel>> drawables;
    for (const Model* level : levels) drawables.push_back(make_drawable_model(*level, nullptr, threads));
    const std::size_t views = measured.distances.size() * direction_count;
    std::vector<std::vector<double>> per_view(views, std::vector<double>(levels.size()));
    parallel_for(views, threads, [&](std::size_t v) {
        // The square of the screen around the model's sphere (its centre part
        // where that is wider than measure_pixels): the same camera, its field
        // narrowed by pixels / resolution.
        const double distance = measured.distances[v / direction_count];
        const double sphere_pixels = double(screen.resolution) * framing.radius / (distance * tangent);
        const double largest = std::max(16.0, std::min(double(measure_pixels), double(screen.resolution)));
        const int pixels = int(std::clamp(std::ceil(1.25 * sphere_pixels), 16.0, largest));
        const float fovy = float(2 * std::atan(tangent * pixels / double(screen.resolution)) * 180 / M_PI);
        const Camera camera =
            framed_camera(framing, measured_directions[v % direction_count], float(distance), fovy);
        const int samples = std::clamp(int(largest) / pixels, 1, max_supersampling);  // .h: measure_pixels
        const Shot seen = render_view(reference->drawable, camera, drawn, pixels, samples);
        const FlipReference prepared = prepare_flip_reference(seen.image, 67, 1);
        for (std::size_t l = 0; l < levels.size(); ++l) {
            const Shot level = render_view(drawables[l]->drawable, camera, drawn, pixels, samples);
            per_view[v][l] =
                covered_mean(flip(prepared, level.image, 1).error, seen.coverage, level.coverage);
        }
    });
    measured.errors.assign(levels.size(), std::vector<double>(measured.distances.size(), 0));
    for (std::size_t v = 0; v < views; ++v)  // summed in view order: the same for any thread count
        for (std::size_t l = 0; l < levels.size(); ++l)
            measured.errors[l][v / direction_count] += per_view[v][l] / direction_count;
    return measured;
}

std::vector<double> switch_distances(const ErrorByDistance& measured, double threshold) {
    std::vector<double> switches;
    for (const std::vector<double>& errors : measured.errors) {
        double from = std::numeric_limits<double>::infinity();
        for (std::size_t d = errors.size(); d-- > 0 && errors[d] <= threshold;) from = measured.distances[d];
        switches.push_back(from);
    }
    return switches;
}

std::vector<std::size_t> reachable_levels(const std::vector<double>& switches,
                                          const std::vector<std::uint64_t>& bytes) {
    auto from = [&](std::size_t k) { return k == 0 ? 0.0 : switches[k]; };  // the finest is drawn from 0 on
    // At each distance a chain draws the cheapest level within the threshold there: levels by the
    // distance they switch in at (the finer first among equals), each kept where it becomes the cheapest.
    std::vector<std::size_t> order;
    for (std::size_t c = 1; c < switches.size(); ++c)
        if (std::isfinite(switches[c])) order.push_back(c);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return from(a) < from(b); });
    std::vector<std::size_t> kept{0};
    for (std::size_t c : order) {
        if (bytes[c] >= bytes[kept.back()]) continue;  // a cheaper level is drawn here already
        if (kept.size() > 1 && from(c) == from(kept.back()))
            kept.pop_back();  // switching in together: never drawn
        kept.push_back(c);
    }
    return kept;
}

}  // namespace boxlod
