#include "experiments/sweep/sweep_shots.h"

#include "base/key_values.h"
#include "toolkit/metrics/image_metrics.h"
#include "toolkit/metrics/metric_registry.h"

namespace boxlod {

RenderSettings view_settings(const Framing& framing, const std::string& view, float multiple, RenderMode mode,
                             const LodParameters& lod, int threads) {
    const Camera camera = framed_camera(framing, *camera_direction(view),
                                        multiple * framing_distance(framing, lod.fovy), lod.fovy);
    return drawing_settings(camera, mode, lod, threads);
}

double choice_error(const std::vector<Metric>& metrics, const std::vector<double>& values) {
    for (Metric preferred :
         {Metric::flip, Metric::flip_covered, Metric::ssim, Metric::rmse, Metric::psnr, Metric::iou})
        for (std::size_t i = 0; i < metrics.size(); ++i) {
            if (metrics[i] != preferred) continue;
            if (preferred == Metric::ssim || preferred == Metric::iou) return 1 - values[i];
            return preferred == Metric::psnr ? -values[i] : values[i];
        }
    return 0;
}

Metrics compare_shots(const SweepConfig& config, const Shot& reference, const Shot& test, bool want_heatmap,
                      int threads) {
    MetricPair pair{reference.image,
                    test.image,
                    &reference.coverage,
                    &test.coverage,
                    reference.flip_reference ? &*reference.flip_reference : nullptr,
                    config.pixels_per_degree,
                    threads};
    MetricValues measured = measure_metrics(config.metrics, pair);
    Metrics out;
    for (double value : measured.values)
        out.values.push_back(format_number(value));  // psnr of identical images: inf
    out.error = choice_error(config.metrics, measured.values);
    if (want_heatmap)
        out.heatmap = measured.flip_error ? std::move(*measured.flip_error)
                                          : rgb_error_map(reference.image, test.image);
    return out;
}

}  // namespace boxlod
