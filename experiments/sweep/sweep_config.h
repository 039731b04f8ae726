// The configuration of `boxlod sweep`: a plain-text file of `key = value`
// lines (`#` comments, lists comma-separated) naming the models, level modes,
// box kinds, interpolations, levels, views, distances, render modes, image
// size, metrics, which images to keep, and any LoD parameter the sweep does
// not vary (toolkit/lod/lod_parameters.h). Paths are relative to the file.
#pragma once
#include "renderer/renderer.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/lod_parameters.h"
#include "toolkit/lod/pages/boxes.h"
#include "toolkit/metrics/metric_registry.h"

#include <string>
#include <vector>

namespace boxlod {

// The images a sweep keeps (names and help in the table).
enum class KeptImages { none, lod, all };
std::span<const EnumEntry<KeptImages>> kept_images();

// The distance the LoD textures are sized for (docs/design.md: Texture sizing):
// nearest: one LoD per level, baked for the smallest of the distances (it is
// texel-exact there and oversampled farther away); each_distance: an LoD per
// level and distance, baked for that distance (texture memory against distance);
// per_level: level c baked for the smallest distance x 2^(c-1), as an engine's
// chain (`build --level-distances auto`) ships it.
enum class SizingRule { nearest, each_distance, per_level };

// The baselines a sweep compares the LoDs with (docs/sweeps.md).
enum class Baseline {
    simplification,
    simplification_best,
    cgal,
    single_box,
    impostor,
    proxy_baked,
    file_lods
};
std::span<const EnumEntry<Baseline>> baselines();  // names and help
std::span<const EnumEntry<SizingRule>> sizing_rules();

struct SweepModel {
    std::string name;    // as written in the config: the CSV's `model` column
    std::string path;    // resolved against the config's folder; empty for a sample
    std::string sample;  // `sample:NAME`: a built-in grammar generated in memory
};

struct SweepConfig {
    std::vector<SweepModel> models;
    std::vector<LevelMode> level_modes{LevelMode::top_down};
    std::vector<BoxKind> box_kinds{BoxKind::expanded};
    std::vector<Interpolation> interpolations{Interpolation::linear};
    std::vector<int> levels;                   // empty: all, 0 .. obtained levels
    std::vector<std::string> views{"+X+Y+Z"};  // camera position names
    std::vector<float> distances{1};           // multiples of the model's framing distance
    std::vector<RenderMode> render_modes{RenderMode::normal};
    int width = 512, height = 512;
    int supersampling = 1;  // renders k times as large a side, averaged over k x k pixels (shot.h)
    std::vector<Metric> metrics = all_metrics();
    double pixels_per_degree = 67;  // FLIP's
    // Every LoD's parameters but those the sweep varies (level mode, box kind,
    // interpolation, level, render mode, sizing distance), set in the config
    // under their parameter-file keys. `fovy` is the views' too.
    LodParameters lod = [] {
        LodParameters p;
        p.resolution = 512;  // texel = pixel on the sweep's default 512-pixel-high images
        return p;
    }();
    SizingRule sizing = SizingRule::per_level;  // `manual = true`: nearest, the manual's one distance
    std::vector<Baseline> baselines;            // none by default; they run in the table's order
    int impostor_directions = 8;                // K: the impostor baseline's K x K captured directions
    KeptImages keep_images = KeptImages::none;
    int threads = 0;  // 0 = all cores
};

// `file` names the source in errors ("file: line N: key: what"); relative
// model paths are resolved against file's folder. Throws InputError.
SweepConfig parse_sweep_config(const std::string& text, const std::string& file);
// Every key a config may have: the sweep's own and the LoD parameters it may set.
std::vector<std::string> sweep_config_keys();
SweepConfig load_sweep_config(const std::string& path);

// The most rows the sweep can make, known before any model is read: per
// model, each variant and baseline at most one group per level (the levels
// listed, else wanted_levels or the budgets, and level 0), each group a row
// per view, distance and render mode.
double most_sweep_rows(const SweepConfig& config);
// What a row takes while the sweep runs: its results.csv and timings.csv
// lines and keys, held in memory (about 1 kB; docs/sweeps.md).
constexpr double sweep_row_memory = 1024;

// What every row of a sweep shares but its key columns do not name (image size,
// FLIP's pixels per degree, sizing rule, impostor directions, the LoD parameters
// it does not vary), as `key = value` lines: a re-run into a folder made with
// other settings would mix rows of two experiments.
std::string sweep_settings(const SweepConfig& config);

}  // namespace boxlod
