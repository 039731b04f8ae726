// A sweep row's picture and its comparison with the original's: the render
// from one of the manual's views as the metrics need it, and the config's
// metrics of a pair (docs/sweeps.md). One thread each in a sweep: rows are
// drawn side by side.
#pragma once
#include "experiments/sweep/sweep_config.h"
#include "renderer/renderer.h"
#include "toolkit/metrics/shot.h"
#include "toolkit/model/framing.h"

#include <optional>
#include <string>
#include <vector>

namespace boxlod {

// The manual's camera position `view`, `multiple` times the framing distance
// away (as `boxlod render --camera`), drawn in `mode` with the LoD's parallax.
RenderSettings view_settings(const Framing& framing, const std::string& view, float multiple, RenderMode mode,
                             const LodParameters& lod, int threads);

struct Metrics {
    std::vector<std::string> values;  // in the config's metric order, as results.csv writes them
    Plane heatmap;                    // FLIP's error when computed, else the RGB error; only when asked
    double error = 0;                 // what simplification-best minimizes (choice_error)
};

// One error, lower = better, from the metrics measured: FLIP if measured, else
// 1 - SSIM, else RMSE, else -PSNR, else 1 - IoU.
double choice_error(const std::vector<Metric>& metrics, const std::vector<double>& values);

// The config's metrics of `test` against `reference` (its prepared FLIP half when it has one).
Metrics compare_shots(const SweepConfig& config, const Shot& reference, const Shot& test, bool want_heatmap,
                      int threads);

}  // namespace boxlod
