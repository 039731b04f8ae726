// ꟻLIP for LDR images: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström,
// Fairchild 2020, "FLIP: A Difference Evaluator for Alternating Images"
// (Proc. ACM Comput. Graph. Interact. Tech. 3(2), HPG 2020). Written from the
// paper's definitions:
// - colour pipeline: sRGB -> linear RGB -> YyCxCz; each channel filtered by
//   its contrast sensitivity function (a sum of Gaussians with the paper's
//   a1, b1, a2, b2 per channel); back to linear RGB clamped to [0, 1];
//   CIELAB with the Hunt adjustment (a*, b* scaled by 0.01 L*); the HyAB
//   distance raised to qc = 0.7 and mapped to [0, 1] against the largest
//   distance cmax (green against blue) with pc = 0.4, pt = 0.95;
// - feature pipeline: edges and points from first and second derivatives of
//   a Gaussian (peak-to-trough width 0.082 degrees) on the achromatic channel
//   Y / Yn; the magnitudes' differences, the larger one scaled by 1/sqrt(2)
//   and raised to qf = 0.5;
// - per pixel deltaE = deltaEc ^ (1 - deltaEf).
// Filter borders replicate the edge pixels. The error is in [0, 1]: 0 for
// identical images, about 0.967 for black against white.
#pragma once
#include "base/input_error.h"
#include "renderer/image.h"
#include "toolkit/metrics/separable_filter.h"
#include "toolkit/metrics/silhouette.h"

namespace boxlod {

struct FlipResult {
    double mean = 0;  // the mean of `error` over all pixels
    Plane error;      // per pixel deltaE, same size as the images
};

// `reference` and `test` are 8-bit sRGB images (3 or more channels, alpha
// ignored) of the same size; `pixels_per_degree` is the observer's angular
// resolution (67 is a 0.7 m wide 4K monitor seen from 0.7 m, the paper's
// default). Throws std::invalid_argument on different sizes or ppd <= 0.
// The observer's pixels per degree a user may ask for: FLIP's filters grow with it.
constexpr NumberRange pixels_per_degree_range{1, 300};

FlipResult flip(const Image8& reference, const Image8& test, double pixels_per_degree = 67, int threads = 0);

// The reference's half of the work, done once when many test images are
// compared with one reference (a sweep compares every LoD of a view with one
// original): its filtered, Hunt-adjusted L*a*b* and its edge and point
// magnitudes. flip(prepare_flip_reference(r, ppd), t) == flip(r, t, ppd), bit for bit.
struct FlipReference {
    double pixels_per_degree = 67;
    Image8 image;  // the reference itself: where a test image equals it, so does the perception
    Plane lab[3], edges, points;
};
FlipReference prepare_flip_reference(const Image8& reference, double pixels_per_degree = 67, int threads = 0);
FlipResult flip(const FlipReference& reference, const Image8& test, int threads = 0);

// The mean of a per-pixel error (FLIP's) over the pixels either image
// covers, 0 where neither covers any: a building's error as the viewer sees
// it, where whole-image error shrinks with the building's pixels and makes
// far levels look free (docs/cost.md: Switching levels). Throws
// std::invalid_argument on sizes that differ.
double covered_mean(const Plane& error, const Coverage& reference, const Coverage& test);

}  // namespace boxlod
