// `boxlod city`: a fly-through of a generated city with run-time LoD selection
// (docs/city.md). Every distinct building design gets its own LoD, built once
// at the origin and drawn moved to each lot that shows it: level c in
// 1..N baked for a sizing distance that doubles with c (base · 2^(c-1)), so that
// texel-exact selection has levels to choose from. Per frame the strategy
// (with hysteresis, optionally under a face budget) picks every building's
// level; the frame is rendered with the streets, and on sampled frames
// compared with full detail (every building at level 0).
#pragma once
#include "data_gen/city.h"
#include "experiments/city/camera_path.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/drawing/packed_drawable.h"
#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/model/cost.h"
#include "toolkit/selection/lod_selection.h"

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace boxlod {

struct FlyThroughOptions {
    Strategy strategy = TexelExact{};
    double detail = 1;                       // the strategy's level-of-detail bias (scale_detail)
    double hysteresis = 0.1;                 // Selector margin h
    std::optional<std::size_t> face_budget;  // faces drawn per frame, streets included
    int width = 320, height = 240;
    float fovy = 45;
    int error_every = 10;           // compare frames 0, K, 2K, ... with full detail; 0: never
    double pixels_per_degree = 67;  // FLIP's observer
    // The levels: every building's LoD parameters (level mode, wanted levels,
    // kept sub-trees, ...; by default the chain that pays its way), level c
    // baked where the chain sizes it (base_distance · 2^(c-1), capped by budgets: chain.h) on a screen
    // `height` pixels high with `fovy` (texel = pixel there), so those three are set per level.
    LodParameters levels;
    float base_distance = 20;
    // Unpacked levels kept between frames (docs/city.md: Memory); a frame's own levels are always unpacked.
    std::size_t memory_budget = std::size_t(1) << 30;
    // A frame compared with full detail unpacks its buildings' originals apart
    // from that cache, about this many bytes at a time; the picture is the same for any value.
    std::size_t full_detail_group_bytes = std::size_t(256) << 20;
    // Lots whose designs derive to the same content (by digest) share one LoD;
    // false: every lot builds its own (the same levels, built again).
    bool share_designs = true;
    int threads = 0;  // 0 = all cores
};

// One design's LoD at the origin, built once for every lot that shows it.
struct DesignLevels {
    std::vector<std::size_t> triangles;  // per level 0..N
    std::vector<CostParts> costs;        // per level 0..N
    // Per level 0..N (level 0: the design's own geometry), packed; the city draws in
    // normal mode, so without height maps. The grammars' textures are shared, not packed.
    std::vector<PackedDrawable> levels;
    SelectionObject object;  // its root box, levels' faces, sizings (errors if measured)
    Bounds bounds;
};

// A lot's building: its design's levels moved to the lot.
struct CityBuilding {
    std::string name;
    std::size_t design = 0;  // into CityLevels::designs
    Eigen::Vector3f translation = Eigen::Vector3f::Zero();
};

// Everything a fly-through draws, built once.
struct CityLevels {
    DecodedTextures textures;  // the streets'; the designs' levels share these and their own by content
    Drawable streets;
    std::size_t street_faces = 0, street_triangles = 0;
    CostParts street_cost;
    std::vector<DesignLevels> designs;
    std::vector<CityBuilding> buildings;
    std::vector<SelectionObject> objects;  // per building: its design's, moved to its lot
    Bounds bounds;                         // the city's
    int max_level = 0;                     // K, the largest N of any building
    double seconds = 0;
    std::size_t packed_bytes = 0;    // every level of every design, packed
    std::size_t unpacked_bytes = 0;  // the same unpacked: what keeping them all decoded would take
};

// The city's streets, and an LoD per distinct design the lots show (or per lot
// without options.share_designs). With `measure_error`, each level's error
// (1 - SSIM against level 0, one render from +X+Y+Z at its sizing distance) is
// recorded for texel-exact selection under a budget. Deterministic for any
// thread count, with or without sharing; progress (one line per LoD built) to
// `progress` when not null.
CityLevels build_city_levels(const CityPlan& city, const FlyThroughOptions& options, bool measure_error,
                             std::FILE* progress = nullptr);

// The camera of a pose for the city: up = +Y (-Z when looking straight down, +Z straight
// up), near and far fitted to the city's bounds.
Camera pose_camera(const CameraPose& pose, const Bounds& city, float fovy_degrees);

struct ImageErrors {
    double psnr = 0, ssim = 0, flip = 0;
};

struct FrameRecord {
    std::vector<int> levels;  // per building
    std::size_t faces = 0, triangles = 0;
    ModelCost cost;  // streets and every building at its level; a texture shared by content counted once
    std::size_t levels_changed = 0;    // buildings whose level differs from the previous frame's
    std::optional<ImageErrors> error;  // on sampled frames
    std::size_t levels_unpacked = 0,
                resident_bytes = 0;  // levels unpacked for the frame; unpacked bytes after it
    // select: every building's level (and the face budget); unpack: the levels not resident
    double select_seconds = 0, unpack_seconds = 0, render_seconds = 0, error_seconds = 0;
};

// Renders every pose; `frame_done(index, image, record)` receives each frame as it is made.
using FrameDone = std::function<void(int, const Image8&, const FrameRecord&)>;
std::vector<FrameRecord> fly_through(const CityLevels& city, const std::vector<CameraPose>& path,
                                     const FlyThroughOptions& options, const FrameDone& frame_done = nullptr);

// One pass over the path at one detail.
struct FlyThroughRun {
    double detail = 1;
    std::vector<FrameRecord> frames;
};

// frames.csv: `frame,strategy,detail,faces,triangles,draw_calls,mesh_bytes,texture_bytes,
// texture_bytes_gpu,bytes,buildings,level_0,...,level_K,
// levels_changed,psnr,ssim,flip`, one row per frame of each run, runs in order; the
// strategy is format_strategy's text (quoted: it has commas); the errors are empty on
// frames not sampled. Deterministic.
std::string frames_csv(const std::vector<FlyThroughRun>& runs, const CityLevels& city,
                       const Strategy& strategy);
// timings.csv: `frame,detail,select_seconds,unpack_seconds,render_seconds,levels_unpacked,resident_bytes`.
std::string timings_csv(const std::vector<FlyThroughRun>& runs);

struct FlyThroughReport {
    double detail = 1;
    std::size_t frames = 0, buildings = 0, sampled_frames = 0;
    std::size_t lods_built = 0;  // one per distinct design shown (per lot without sharing)
    double faces_mean = 0;
    std::size_t faces_min = 0, faces_max = 0;
    std::vector<std::size_t> level_totals;  // building-frames at each level 0..K
    std::size_t levels_changed = 0;         // over all frames
    double psnr_mean = 0, ssim_mean = 0,
           flip_mean = 0;  // over the sampled frames (psnr: finite ones; inf if none)
    std::size_t levels_unpacked = 0, resident_peak_bytes = 0;
    std::size_t packed_bytes = 0, unpacked_bytes = 0;  // CityLevels'
    double build_seconds = 0, select_seconds = 0, unpack_seconds = 0, render_seconds = 0, error_seconds = 0,
           total_seconds = 0;
};

// What a fly-through of a city needs besides its cache of unpacked levels
// (memory_budget): per LoD built its packed levels, per building its selection
// and its level in a frame, a group of originals for the frames compared at
// full detail, and the frame's render and metrics (docs/city.md: Memory).
double fly_through_memory(const CityPlan& city, const FlyThroughOptions& options);

// What run_fly_through writes into its folder (a path relative to it):
// frames.csv, timings.csv, and per run (in detail_D/ when several) frames/,
// frames/frame_NNNN.png and contact_sheet.png.
bool is_fly_through_file(const std::string& name);

// Whether build_city_levels must measure levels' errors for the strategy:
// texel-exact selection under an error budget reads them.
bool needs_measured_errors(const Strategy& strategy);

// The whole command after the levels are built: one pass over the path per detail
// (options.detail is ignored). Frames go to OUTDIR/frames/frame_NNNN.png and up to 16
// of them, spread over the path and labelled with frame and faces, to
// OUTDIR/contact_sheet.png; with several details, to OUTDIR/detail_<K>/frames/ and
// OUTDIR/detail_<K>/contact_sheet.png. frames.csv and timings.csv hold every run.
// Every file is written atomically. One report per detail.
std::vector<FlyThroughReport> run_fly_through(const CityLevels& levels, const std::vector<CameraPose>& path,
                                              const FlyThroughOptions& options,
                                              const std::vector<double>& details,
                                              const std::string& output_folder,
                                              std::FILE* progress = nullptr);

}  // namespace boxlod
