// boxlod as a library: the jobs of the command line in one header, each with
// its contract. A level is what `boxlod build --level c` writes, a chain what
// `--chain` holds, levels by budget what `--budgets ... --all-levels` writes
// (docs/design.md is the truth for what they mean; docs/api_example.cpp uses
// every function). Link the boxlod_toolkit library.
//
// Errors: every function throws boxlod::InputError (base/input_error.h), one
// line naming the file or parameter and what is wrong, for input it refuses;
// anything else it throws is a bug. Threads: `threads` 0 uses every core (at
// most 1024); the results are byte-identical for any count. The functions keep no state
// between calls: call them from any thread, on models no other thread changes.
#pragma once
#include "base/key_values.h"
#include "renderer/renderer.h"
#include "toolkit/lod/lod_parameters.h"
#include "toolkit/metrics/shot.h"
#include "toolkit/model/model.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace boxlod {

// The model at `path`: glTF/GLB, CityJSON (.city.json, .jsonl), IFC (2x to
// 4x3, through web-ifc in a child process) and what assimp reads;
// FILE#OBJECT is one object of a city file. `city_lod` picks a CityJSON LoD
// ("2.2"; "": each object's finest); `chain_level` K > 0 reads level K of a
// chain (build --chain) as an MSFT_lod client draws it.
Model read_model(const std::string& path, const std::string& city_lod = "", int chain_level = 0);

// Writes `model` as glTF: PATH.gltf with its .bin and textures, or one .glb;
// every file complete or none (docs/design.md: Files).
void write_model(const Model& model, const std::string& path);

// A level of detail of a model.
struct Level {
    int level = 0;         // 0: the original as a level
    Model model;           // is_lod; its parameters (Model::lod_params) build it again
    KeyValues statistics;  // docs/design.md: Statistics (bytes_lod, triangles_lod, ...)
    double switch_distance =
        0;  // a chain's: the camera distance in metres from which it is drawn (level 0: 0)
};

// Level `level` (0 .. obtained levels) as `build --level` makes it: sized
// for parameters.distance x 2^(level-1) (0: the framing distance) by the
// parameters' level distances. Refuses bad parameters, a level past those
// obtained, and a byte budget below the coarsest cut.
Level build_level(const Model& model, const LodParameters& parameters, int level, int threads = 0);

// Every level a distance draws, finest first, as `build --chain` holds them
// (at most the 10 finest): each switches in at the nearest distance beyond
// which its FLIP over covered pixels stays within `switch_error` (0: where
// its texels meet the screen's pixels), each cheaper than the one before.
std::vector<Level> build_chain(const Model& model, const LodParameters& parameters,
                               double switch_error = 0.05, int threads = 0);

// One level per byte budget of parameters.budgets (fractions of the
// original's bytes, or sizes), for level modes error-greedy and hybrid, as
// `build --budgets B1,...,BN --all-levels` writes levels 1..N: a level that
// draws what the one before draws is left out, as there.
std::vector<Level> build_levels_by_budget(const Model& model, const LodParameters& parameters,
                                          int threads = 0);

// A camera around a model: from `direction` (from the centre of its bounding
// box towards the camera, e.g. (1, 1, 1)), `distance` times the distance at
// which its bounding sphere fills a vertical field of view of 45 degrees.
struct Viewpoint {
    Eigen::Vector3f direction{1, 1, 1};
    float distance = 1;
    int width = 256, height = 256;
    RenderMode mode = RenderMode::normal;
};

// `model` through `view` around `framed` (the original: a level and its
// original are seen from the same camera), on white: the image and the
// pixels the model covers, as the metrics take them.
Shot render_model(const Model& model, const Model& framed, const Viewpoint& view, int threads = 0);

// How `test` differs from `reference` (same size): as `boxlod compare` measures.
struct Comparison {
    double rmse = 0, psnr = 0, ssim = 0;
    double flip = 0;          // mean FLIP (LDR) over the image, at 67 pixels per degree
    double flip_covered = 0;  // mean FLIP over the pixels either shot covers
    double iou = 0;           // of the covered pixels
};
Comparison compare_renders(const Shot& reference, const Shot& test, int threads = 0);

}  // namespace boxlod
