// Choosing an LoD level at run time (docs/design.md: Selection): a strategy
// turns the object and the view into one continuous value, and the value into
// a level c in 0..N (0 = the original, N = the coarsest). A Selector adds
// hysteresis, so a camera hovering at a threshold does not make the level pop.
// Sources: Ogre3D's PixelCountLodStrategy and ScreenRatioLodStrategy (pixel
// count, screen ratio); E. Slupko, "New Automatic LOD Selection for
// Progressive Meshes" (2020) (box diagonal).
#pragma once
#include "renderer/camera.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/model.h"

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace boxlod {

// An image error of a level against the original (e.g. 1 - SSIM or FLIP), measured
// by a perspective camera at `distance` from the object's center with `fovy_degrees`
// on an image `resolution` pixels high.
struct MeasuredError {
    double error = 0;
    double distance = 100;
    double fovy_degrees = 45;
    double resolution = 1080;
};

struct SelectionLevel {
    std::size_t faces = 0;  // faces drawn at this level (statistics: faces_lod)
    std::optional<TextureSizing>
        sizing;  // the texel = pixel view its boxes were baked for (hybrid: its finest boxes)
    std::optional<MeasuredError> error;  // for texel-exact selection under an error budget
    // For measured switching: the camera distance (metres, for the fovy and
    // resolution its chain was sized for) from which it is drawn, as the
    // chain measured it (chain.h: switched_levels); none: no distance draws it.
    std::optional<double> switch_distance;
};

// The object being drawn: its bounding sphere, optionally its oriented box, and
// its levels 0..N (level 0 is the original: always exact, never needs a sizing).
struct SelectionObject {
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
    float radius = 0;
    std::optional<OrientedBox> box;
    std::vector<SelectionLevel> levels;
};

// The box with its circumscribed sphere (radius = half the diagonal).
SelectionObject selection_object(const OrientedBox& box, std::vector<SelectionLevel> levels);
int coarsest_level(const SelectionObject& object);  // N (0 when there are no levels)

struct SelectionView {
    Camera camera;
    int width = 1024, height = 768;  // viewport in pixels
};

// Level c from distance >= distances[c - 1] on (ascending thresholds).
struct DistanceBands {
    std::vector<double> distances;
};
// Level c once the projected sphere covers fewer than pixels[c - 1] pixels (descending).
struct PixelCount {
    std::vector<double> pixels;
};
// As PixelCount with the pixel count over width * height (descending fractions of the
// screen): the same settings work at any resolution.
struct ScreenRatio {
    std::vector<double> ratios;
};
enum class DiagonalInterpolation { linear, square, square_root };
// The projected box diagonal x in pixels gives a detail weight t in [0, 1]: 0 up to
// min_pixels, 1 from max_pixels on, interpolated in x, x^2 or sqrt(x) between; level
// N - floor(t N).
struct BoxDiagonal {
    double min_pixels = 16, max_pixels = 512;
    DiagonalInterpolation interpolation = DiagonalInterpolation::linear;
};
// The coarsest level whose box textures map at most one texel per pixel (baked for
// a pixel no larger than the current one at the object), and, with a budget, whose
// measured error scaled to the current view stays within it.
struct TexelExact {
    std::optional<double> error_budget;
    double detail = 1;  // judge levels at the pixel footprint / detail (see scale_detail)
};
// Each level from the distance its chain measured it to stay within `error`
// of the original (FLIP over covered pixels; chain.h: switched_levels, as
// `build --chain` and `tiles` switch): the coarsest level whose switch
// distance the camera has passed, judged at the distance / detail.
struct MeasuredSwitch {
    double error = 0.05;
    double detail = 1;
};
using Strategy =
    std::variant<DistanceBands, PixelCount, ScreenRatio, BoxDiagonal, TexelExact, MeasuredSwitch>;

// A level-of-detail bias (the engines' "LOD bias"): the strategy picks levels as if
// every object were seen from 1/detail of its distance, so detail > 1 keeps finer
// levels and detail < 1 coarser ones. Distance bands scale by detail, pixel counts
// and screen ratios by 1/detail^2 (exact for d >> r, where the disc goes as 1/d^2),
// diagonal thresholds by 1/detail, and texel-exact selection judges texels and
// error at the pixel footprint / detail. One knob over every strategy, so each can
// be drawn as a curve of faces against image error.
Strategy scale_detail(const Strategy& strategy, double detail);

// Finite, non-negative, strictly ordered thresholds; min_pixels <= max_pixels; budget >= 0.
// Throws InputError naming `where`.
void validate_strategy(const Strategy& strategy, const std::string& where);

// The measures (all from the Euclidean camera-to-center distance d, so turning the
// camera on the spot never changes a level).
double camera_distance(const SelectionObject& object, const SelectionView& view);
double sphere_pixel_count(const SelectionObject& object, const SelectionView& view);
double box_diagonal_pixels(const SelectionObject& object, const SelectionView& view);
double pixel_footprint(const SelectionObject& object,
                       const SelectionView& view);                   // world size of a pixel at d
double diagonal_weight(const BoxDiagonal& strategy, double pixels);  // t in [0, 1]
// The measured error scaled to a view whose pixel spans `footprint` world units.
double scaled_error(const MeasuredError& error, double footprint);

// The strategy's value: distance, pixel count, screen ratio, diagonal pixels or pixel
// footprint; and the level a value maps to (monotone in the value).
double strategy_value(const Strategy& strategy, const SelectionObject& object, const SelectionView& view);
int level_for_value(const Strategy& strategy, const SelectionObject& object, double value);

struct Choice {
    double value = 0;
    int level = 0;
};
// Without hysteresis. An object of zero radius covers no pixel: level N. A camera inside
// the bounding sphere, or a NaN value (a broken view), gets level 0.
Choice choose_level(const Strategy& strategy, const SelectionObject& object, const SelectionView& view);

// Hysteresis with a relative margin h: the previous level stays while it is still the
// choice for the value multiplied or divided by (1 + h), i.e. until the value has crossed
// the threshold between the two levels by a factor 1 + h. The rules of choose_level for
// zero radius, camera inside and NaN apply at once.
struct Selector {
    double margin = 0.1;  // h
    int level = -1;       // the previous frame's level; -1 before the first frame
};
int select_level(Selector& selector, const Strategy& strategy, const SelectionObject& object,
                 const SelectionView& view);

}  // namespace boxlod
