// The image metrics by name: one table that `compare`, sweep configs and
// `city` read, and one function that measures a list of them on a pair of
// images, sharing the work they have in common (one RMSE for RMSE and PSNR,
// one FLIP for its mean, its mean over covered pixels and its error map).
#pragma once
#include "base/enum_table.h"
#include "base/input_error.h"
#include "renderer/image.h"
#include "toolkit/metrics/flip.h"
#include "toolkit/metrics/separable_filter.h"
#include "toolkit/metrics/silhouette.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace boxlod {

enum class Metric { rmse, psnr, ssim, flip, flip_covered, iou };
std::span<const EnumEntry<Metric>> metrics();  // names ("rmse", ...) and help
std::vector<Metric> all_metrics();

// The values a metric takes: psnr [0, inf], ssim [-1, 1], the others [0, 1]; the bounded ones a hair wider
// (1e-9), as a ratio that is at most 1 may round to 1 + 2^-52. A sweep's tables read back are held to it.
NumberRange metric_range(Metric metric);

// Names, each kept once in the order given; an unknown one throws InputError
// "CONTEXT: unknown metric 'x' (rmse, psnr, ssim, flip, flip_covered, iou)".
std::vector<Metric> parse_metrics(const std::vector<std::string>& names, const std::string& context);

struct MetricPair {
    const Image8& reference;
    const Image8& test;
    const Coverage* reference_coverage = nullptr;  // needed for iou and flip_covered
    const Coverage* test_coverage = nullptr;
    const FlipReference* flip_reference =
        nullptr;                    // the reference's half of FLIP, prepared once per reference
    double pixels_per_degree = 67;  // FLIP's, without a prepared reference
    int threads = 0;
};

struct MetricValues {
    std::vector<double> values;       // one per metric asked, in order (psnr of identical images: inf)
    std::optional<Plane> flip_error;  // FLIP's per-pixel error, when FLIP was measured
};

MetricValues measure_metrics(const std::vector<Metric>& metrics, const MetricPair& pair);

// What measuring every metric of two width x height images needs, the images
// included: 84 bytes a pixel (a little over what `boxlod compare` peaks at),
// FLIP's filtered planes most of it.
double metrics_memory(int width, int height);

}  // namespace boxlod
