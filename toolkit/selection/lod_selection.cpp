#include "toolkit/selection/lod_selection.h"

#include "base/input_error.h"
#include "toolkit/lod/chain/error_by_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace boxlod {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Camera positions are floats: a camera placed at a level's baked distance may
// land a relative 1e-7 closer; texel-exactness forgives that much (and no more
// than 1e-5).
constexpr double texel_tolerance = 1e-5;

// Orthographic pixels per world unit along x and y: the window is stretched over the
// viewport (renderer/camera.h), whatever the distance.
Eigen::Vector2d orthographic_scale(const SelectionView& view) {
    const Camera& c = view.camera;
    auto scale = [](double pixels, double extent) { return extent > 0 ? pixels / extent : infinity; };
    return {scale(view.width, double(c.right) - c.left), scale(view.height, double(c.top) - c.bottom)};
}

// Pixels per world unit at distance d, along the finer screen axis. Perspective:
// f / d with the focal length f = (height / 2) / tan(fovy / 2) in pixels (square
// pixels: the same along x).
double pixels_per_unit(const SelectionView& view, double distance) {
    const Camera& c = view.camera;
    if (c.orthographic) return orthographic_scale(view).maxCoeff();
    double f = view.height / 2.0 / half_fovy_tangent(c.fovy_degrees);
    return distance > 0 ? f / distance : infinity;
}

// How many of `thresholds` the value has passed: `passed(value, threshold)` is
// monotone in the value, so the count is too, whatever the order of the thresholds.
template <typename Passed>
int count_passed(const std::vector<double>& thresholds, double value, Passed passed, int coarsest) {
    int count =
        int(std::count_if(thresholds.begin(), thresholds.end(), [&](double t) { return passed(value, t); }));
    return std::min(count, coarsest);
}

int below(const std::vector<double>& thresholds, double value, int coarsest) {
    return count_passed(
        thresholds, value, [](double v, double t) { return v < t; }, coarsest);
}

int texel_exact_level(const TexelExact& strategy, const SelectionObject& object, double footprint) {
    // Level c is acceptable when its texels are no larger than the current pixel at the
    // object: p >= p_b = pixel_world_size(sizing) (docs/design.md: Texture sizing; the 1:1
    // mapping holds for any view whose pixel is at least as large).
    // The detail bias judges the level as if the pixel were detail times smaller.
    footprint /= strategy.detail;
    // The coarsest acceptable level, sought from the coarsest down: the far
    // buildings of a city, most of them, stop at the first.
    for (int c = coarsest_level(object); c >= 1; --c) {
        const SelectionLevel& level = object.levels[c];
        if (!level.sizing) continue;
        if (!(footprint >= pixel_world_size(*level.sizing) * (1 - texel_tolerance))) continue;
        if (strategy.error_budget &&
            (!level.error || !(scaled_error(*level.error, footprint) <= *strategy.error_budget)))
            continue;
        return c;
    }
    return 0;
}

// The coarsest level whose switch distance `distance` / detail has reached.
int measured_level(const MeasuredSwitch& strategy, const SelectionObject& object, double distance) {
    for (int c = coarsest_level(object); c >= 1; --c) {
        const std::optional<double>& at = object.levels[std::size_t(c)].switch_distance;
        if (at && distance / strategy.detail >= *at) return c;
    }
    return 0;
}

// choose_level's rules that override every strategy.
std::optional<int> forced_level(const SelectionObject& object, const SelectionView& view, double value) {
    if (!(object.radius > 0)) return coarsest_level(object);
    if (camera_distance(object, view) <= object.radius || std::isnan(value)) return 0;
    return std::nullopt;
}

void check(bool ok, const std::string& where, const char* name, const std::string& what) {
    if (!ok) throw_input_error(where, name, what);
}

void check_thresholds(const std::vector<double>& thresholds, bool ascending, const std::string& where,
                      const char* name) {
    for (std::size_t i = 0; i < thresholds.size(); ++i) {
        check(std::isfinite(thresholds[i]) && thresholds[i] >= 0, where, name,
              "thresholds must be finite and non-negative");
        if (i > 0)
            check(ascending ? thresholds[i] > thresholds[i - 1] : thresholds[i] < thresholds[i - 1], where,
                  name,
                  ascending ? "thresholds must increase strictly" : "thresholds must decrease strictly");
    }
}

}  // namespace

SelectionObject selection_object(const OrientedBox& box, std::vector<SelectionLevel> levels) {
    SelectionObject object;
    object.center = box.center;
    object.radius = box.half_extents.norm();
    object.box = box;
    object.levels = std::move(levels);
    return object;
}

int coarsest_level(const SelectionObject& object) { return std::max(0, int(object.levels.size()) - 1); }

void validate_strategy(const Strategy& strategy, const std::string& where) {
    if (auto* s = std::get_if<DistanceBands>(&strategy))
        check_thresholds(s->distances, true, where, "distance bands");
    if (auto* s = std::get_if<PixelCount>(&strategy))
        check_thresholds(s->pixels, false, where, "pixel count");
    if (auto* s = std::get_if<ScreenRatio>(&strategy))
        check_thresholds(s->ratios, false, where, "screen ratio");
    if (auto* s = std::get_if<BoxDiagonal>(&strategy))
        check(std::isfinite(s->min_pixels) && std::isfinite(s->max_pixels) && s->min_pixels >= 0 &&
                  s->min_pixels <= s->max_pixels,
              where, "box diagonal", "needs finite 0 <= min_pixels <= max_pixels");
    if (auto* s = std::get_if<TexelExact>(&strategy))
        check(!s->error_budget || (std::isfinite(*s->error_budget) && *s->error_budget >= 0), where,
              "texel exact", "the error budget must be finite and non-negative");
    if (auto* s = std::get_if<MeasuredSwitch>(&strategy))
        check(s->error >= switch_error_range.min && s->error <= switch_error_range.max, where,
              "measured switching", "the error must be in " + range_text(switch_error_range));
}

Strategy scale_detail(const Strategy& strategy, double detail) {
    if (!(detail > 0) || !std::isfinite(detail))
        throw std::invalid_argument("scale_detail: detail must be positive");
    Strategy out = strategy;
    auto scale = [](std::vector<double>& values, double factor) {
        for (double& v : values) v *= factor;
    };
    if (auto* s = std::get_if<DistanceBands>(&out)) scale(s->distances, detail);
    if (auto* s = std::get_if<PixelCount>(&out)) scale(s->pixels, 1 / (detail * detail));
    if (auto* s = std::get_if<ScreenRatio>(&out)) scale(s->ratios, 1 / (detail * detail));
    if (auto* s = std::get_if<BoxDiagonal>(&out)) {
        s->min_pixels /= detail;
        s->max_pixels /= detail;
    }
    if (auto* s = std::get_if<TexelExact>(&out)) s->detail *= detail;
    if (auto* s = std::get_if<MeasuredSwitch>(&out)) s->detail *= detail;
    return out;
}

double camera_distance(const SelectionObject& object, const SelectionView& view) {
    return (view.camera.position.cast<double>() - object.center.cast<double>()).norm();
}

double sphere_pixel_count(const SelectionObject& object, const SelectionView& view) {
    double r = object.radius;
    if (!(r > 0)) return 0;
    if (view.camera.orthographic) {
        // pi r^2 over the window area, in pixels (screen-ratio-lod-strategy.txt, PT_ORTHOGRAPHIC:
        // bounding area / ortho area, times the viewport's pixels); pi (r height / (top - bottom))^2
        // when the window has the viewport's aspect.
        Eigen::Vector2d scale = orthographic_scale(view);
        return M_PI * r * r * scale.x() * scale.y();
    }
    // The sphere's silhouette seen from distance d is the circle where its tangent cone
    // (half-angle asin(r / d)) meets the image plane: radius f tan(asin(r / d)) =
    // f r / sqrt(d^2 - r^2) pixels. Exact for a sphere on the view axis; elsewhere the
    // silhouette is an ellipse stretched towards the screen edge and this is the standard
    // approximation (Mara and McGuire, "2D Polyhedral Bounds of a Clipped, Perspective-
    // Projected 3D Sphere", JCGT 2(2), 2013). For d >> r it becomes pi (r f / d)^2, a
    // quarter of Ogre's PixelCount/ScreenRatio value (screen-ratio-lod-strategy.txt
    // measures in NDC, 2 units per screen side, hence its "values generally higher than
    // the actual area").
    double d = camera_distance(object, view);
    if (d <= r) return infinity;  // the sphere fills the view
    double f = pixels_per_unit(view, 1);
    return M_PI * (r * f) * (r * f) / ((d - r) * (d + r));
}

double box_diagonal_pixels(const SelectionObject& object, const SelectionView& view) {
    // interpolated-lod-selection.txt: the extents' diagonal times the viewport's pixels per
    // unit at the object (the larger of x and y); the diagonal is measured as if it lay in
    // the plane through the center facing the camera. Without a box, the diagonal of any
    // box inscribed in the sphere: 2 r.
    double diagonal = object.box ? 2 * double(object.box->half_extents.norm()) : 2 * double(object.radius);
    if (!(diagonal > 0)) return 0;
    return diagonal * pixels_per_unit(view, camera_distance(object, view));
}

double pixel_footprint(const SelectionObject& object, const SelectionView& view) {
    // Perspective: p = 2 d tan(fovy / 2) / height, the same formula as pixel_world_size
    // (docs/design.md: Texture sizing) for the current camera at the object's distance.
    return 1 / pixels_per_unit(view, camera_distance(object, view));
}

double diagonal_weight(const BoxDiagonal& s, double x) {
    // interpolated-lod-selection.txt: below minPixels the least detail, above maxPixels the
    // most, in between LOD = A g(x) + B through (minPixels, least) and (maxPixels, most),
    // with g(x) = x (the custom linear example), x^2 (kSqrInterpolation) or sqrt(x)
    // (kSqrtInterpolation).
    if (!(x > s.min_pixels)) return 0;
    if (x >= s.max_pixels) return 1;
    auto g = [&](double v) {
        switch (s.interpolation) {
        case DiagonalInterpolation::square: return v * v;
        case DiagonalInterpolation::square_root: return std::sqrt(v);
        case DiagonalInterpolation::linear: break;
        }
        return v;
    };
    return std::clamp((g(x) - g(s.min_pixels)) / (g(s.max_pixels) - g(s.min_pixels)), 0.0, 1.0);
}

double scaled_error(const MeasuredError& error, double footprint) {
    // The deviations a box leaves (a cornice it flattens, a recess it fills) have a fixed
    // world size, so their size in pixels, and to first order the error they cause, falls
    // in proportion to the pixels per world unit: e(p) = e_ref p_ref / p, which is
    // e_ref d_ref / d for the measuring camera's fovy and resolution. A model for the
    // sweeps to check, not a measurement.
    if (!(error.error > 0)) return 0;
    if (!(footprint > 0)) return infinity;
    TextureSizing reference;
    reference.fovy_degrees = float(error.fovy_degrees);
    reference.distance = float(error.distance);
    reference.resolution = float(error.resolution);
    return error.error * pixel_world_size(reference) / footprint;
}

double strategy_value(const Strategy& strategy, const SelectionObject& object, const SelectionView& view) {
    if (std::holds_alternative<DistanceBands>(strategy) || std::holds_alternative<MeasuredSwitch>(strategy))
        return camera_distance(object, view);
    if (std::holds_alternative<PixelCount>(strategy)) return sphere_pixel_count(object, view);
    if (std::holds_alternative<ScreenRatio>(strategy)) {
        // screen-ratio-lod-strategy.txt: the pixel count over the screen's, so that a
        // threshold means the same share of the screen at any resolution.
        double screen = double(view.width) * view.height;
        return screen > 0 ? sphere_pixel_count(object, view) / screen : infinity;
    }
    if (std::holds_alternative<BoxDiagonal>(strategy)) return box_diagonal_pixels(object, view);
    return pixel_footprint(object, view);
}

int level_for_value(const Strategy& strategy, const SelectionObject& object, double value) {
    int n = coarsest_level(object);
    if (auto* s = std::get_if<DistanceBands>(&strategy))
        return count_passed(
            s->distances, value, [](double v, double t) { return v >= t; }, n);
    if (auto* s = std::get_if<PixelCount>(&strategy)) return below(s->pixels, value, n);
    if (auto* s = std::get_if<ScreenRatio>(&strategy)) return below(s->ratios, value, n);
    if (auto* s = std::get_if<BoxDiagonal>(&strategy))
        // Detail floor(t N) as the reference truncates, counted from the coarsest level.
        return n - std::clamp(int(std::floor(diagonal_weight(*s, value) * n)), 0, n);
    if (auto* s = std::get_if<MeasuredSwitch>(&strategy)) return measured_level(*s, object, value);
    return texel_exact_level(std::get<TexelExact>(strategy), object, value);
}

Choice choose_level(const Strategy& strategy, const SelectionObject& object, const SelectionView& view) {
    Choice choice;
    choice.value = strategy_value(strategy, object, view);
    auto forced = forced_level(object, view, choice.value);
    choice.level = forced ? *forced : level_for_value(strategy, object, choice.value);
    return choice;
}

int select_level(Selector& selector, const Strategy& strategy, const SelectionObject& object,
                 const SelectionView& view) {
    Choice choice = choose_level(strategy, object, view);
    bool first = selector.level < 0;
    // The level staying as it was is the common case, and needs no more: a
    // level monotone in the value lies between those of value / factor and value x factor.
    if (first || selector.level == choice.level || forced_level(object, view, choice.value)) {
        selector.level = choice.level;
        return selector.level;
    }
    double factor = 1 + std::max(0.0, selector.margin);
    int a = level_for_value(strategy, object, choice.value * factor);
    int b = level_for_value(strategy, object, choice.value / factor);
    if (selector.level < std::min(a, b) || selector.level > std::max(a, b)) selector.level = choice.level;
    return selector.level;
}

}  // namespace boxlod
