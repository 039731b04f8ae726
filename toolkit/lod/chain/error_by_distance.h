// A chain's levels judged where they are seen (docs/cost.md: Switching
// levels): each level's ꟻLIP against the original over the pixels either
// covers (metrics/flip.h: covered_mean), the mean over four raised diagonal
// views, at distances from the framing distance outwards in half octaves to
// where the model's bounding sphere spans `few_pixels` of the screen. The
// screen is the sizing camera's (fovy, `resolution` pixels high); a view
// renders the square of it around the model's sphere, at most its centre
// `measure_pixels` (the same camera with a narrower field), so a pixel is the
// screen's at every distance and a far view costs less than a near one. From the errors follow the switch
// distances: level c is drawn from the nearest distance beyond which its
// error stays within a threshold, and a chain keeps the levels that some
// distance draws, each cheaper than the one before it.
#pragma once
#include "renderer/scene.h"
#include "toolkit/lod/lod_parameters.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace boxlod {

constexpr int measure_pixels = 384;  // the largest side of a measured view
// A view of p pixels a side is rendered min(n / p, 4) times as large a side,
// n the nearest view's side (measure_pixels or the screen's height, the
// smaller), and averaged (metrics/shot.h: render_shot): a far building's
// windows and edges below a pixel blend as an anti-aliased client shows them,
// where one sample each measured aliasing (docs/cost.md: Judged where they are
// seen), and no view costs more pixels than the nearest.
constexpr double few_pixels = 4;  // where the measured distances end: the sphere this wide on the screen
constexpr NumberRange switch_error_range{1e-4, 1};  // a threshold of covered ꟻLIP

// A switch error is 0 (switch at the sizing distance) or in switch_error_range;
// else throws InputError naming `what` (an option, a strategy).
void check_switch_error(double error, const std::string& what);

struct ErrorByDistance {
    std::vector<double> distances;            // ascending, from the framing distance
    std::vector<std::vector<double>> errors;  // per level given, per distance
};

// The distances measured for `original` seen on `screen` (its fovy and resolution).
std::vector<double> measured_distances(const Model& original, const TextureSizing& screen);

// `levels` against `original`, drawn in the parameters' render mode and
// parallax; the same for any thread count.
ErrorByDistance measure_error_by_distance(const Model& original, const std::vector<const Model*>& levels,
                                          const TextureSizing& screen, const LodParameters& drawn,
                                          int threads);

// Per level, the nearest measured distance from which on its error is at most
// `threshold`; infinity where its error at the farthest exceeds it.
std::vector<double> switch_distances(const ErrorByDistance& measured, double threshold);

// The levels a chain keeps, as indices into the levels given (the first, the
// finest, always kept and drawn from 0 on), in the order a chain draws them:
// at each distance the cheapest level within the threshold there, so each
// kept level switches in farther and costs fewer bytes than the one before.
// A level left out is never needed: a cheaper one is within the threshold
// wherever it would be drawn.
std::vector<std::size_t> reachable_levels(const std::vector<double>& switches,
                                          const std::vector<std::uint64_t>& bytes);

}  // namespace boxlod
