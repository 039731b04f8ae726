#include "toolkit/metrics/metric_registry.h"

#include "base/input_error.h"
#include "toolkit/metrics/image_metrics.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace boxlod {
namespace {

constexpr EnumEntry<Metric> metric_table[] = {
    {Metric::rmse, "rmse", "root mean squared error of the sRGB values over R, G, B (0 = identical)"},
    {Metric::psnr, "psnr", "peak signal-to-noise ratio in dB, peak 1 (inf = identical)"},
    {Metric::ssim, "ssim", "mean SSIM on BT.601 luma, as scikit-image's structural_similarity"},
    {Metric::flip, "flip", "mean LDR FLIP (Andersson et al. 2020) at the given pixels per degree"},
    {Metric::flip_covered, "flip_covered",
     "LDR FLIP's mean over the pixels either image covers (0 where neither does): a building as seen, where "
     "the whole image's mean shrinks with its pixels"},
    {Metric::iou, "iou", "intersection over union of the two coverage masks"},
};

}  // namespace

std::span<const EnumEntry<Metric>> metrics() { return metric_table; }

std::vector<Metric> all_metrics() {
    std::vector<Metric> all;
    for (const EnumEntry<Metric>& entry : metrics()) all.push_back(entry.value);
    return all;
}

NumberRange metric_range(Metric metric) {
    constexpr double rounding = 1e-9;
    switch (metric) {
    case Metric::psnr: return {0, std::numeric_limits<double>::infinity()};
    case Metric::ssim: return {-1 - rounding, 1 + rounding};
    default: return {-rounding, 1 + rounding};
    }
}

std::vector<Metric> parse_metrics(const std::vector<std::string>& names, const std::string& context) {
    std::vector<Metric> out;
    for (const std::string& name : names) {
        Metric metric{};
        if (!parse_enum(metrics(), name, metric))
            throw InputError(context + ": unknown metric '" + name + "' (" + enum_names(metrics()) + ")");
        if (std::find(out.begin(), out.end(), metric) == out.end()) out.push_back(metric);
    }
    return out;
}

double metrics_memory(int width, int height) { return 84.0 * double(width) * double(height); }

MetricValues measure_metrics(const std::vector<Metric>& wanted, const MetricPair& pair) {
    MetricValues out;
    std::optional<double> error;
    std::optional<FlipResult> flipped;  // measured once for flip and flip_covered
    auto flip_result = [&]() -> const FlipResult& {
        if (!flipped)
            flipped = pair.flip_reference
                          ? flip(*pair.flip_reference, pair.test, pair.threads)
                          : flip(pair.reference, pair.test, pair.pixels_per_degree, pair.threads);
        return *flipped;
    };
    auto coverages = [&](Metric metric) {
        if (!pair.reference_coverage || !pair.test_coverage)
            throw std::logic_error(std::string("measure_metrics: ") + enum_name(metrics(), metric) +
                                   " needs both coverages");
    };
    for (Metric metric : wanted) {
        switch (metric) {
        case Metric::rmse:
        case Metric::psnr:
            if (!error) error = rmse(pair.reference, pair.test);
            out.values.push_back(metric == Metric::rmse ? *error : psnr_from_rmse(*error));
            break;
        case Metric::ssim: out.values.push_back(ssim(pair.reference, pair.test, pair.threads)); break;
        case Metric::flip: out.values.push_back(flip_result().mean); break;
        case Metric::flip_covered:
            coverages(metric);
            out.values.push_back(
                covered_mean(flip_result().error, *pair.reference_coverage, *pair.test_coverage));
            break;
        case Metric::iou:
            coverages(metric);
            out.values.push_back(silhouette_iou(*pair.reference_coverage, *pair.test_coverage));
            break;
        }
    }
    if (flipped) out.flip_error = std::move(flipped->error);
    return out;
}

}  // namespace boxlod
