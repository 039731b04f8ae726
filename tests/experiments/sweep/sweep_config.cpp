#include "experiments/sweep/sweep_config.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace boxlod {
namespace {

TEST(SweepConfig, ParsesListsAndResolvesPathsAgainstTheConfigFolder) {
    SweepConfig c = parse_sweep_config(
        "# a sweep\n"
        "models = house.glb, /data/fzk.ifc, sample:manual\n"
        "level_modes = top-down, box-volume   # comment\n"
        "box_kinds = expanded, minimal\n"
        "interpolations = linear, rank\n"
        "levels = 3, 0, 1\n"
        "wanted_levels = 5\n"
        "views = +X+Y+Z, -Z\n"
        "distances = 1, 2.5\n"
        "render_modes = normal, parallax\n"
        "width = 64\nheight = 48\nfovy = 30\n"
        "metrics = psnr, ssim\n"
        "ppd = 40\nsupersampling = 2\nresolution = 256\nkeep_images = all\nthreads = 2\n"
        "sizing = each-distance\nbaselines = single-box, simplification\nkeep_small_subtrees = "
        "true\nkeep_cheaper_subtrees = false\n",
        "/work/sweeps/config.txt");
    ASSERT_EQ(c.models.size(), 3u);
    EXPECT_EQ(c.models[0].name, "house.glb");
    EXPECT_EQ(c.models[0].path, "/work/sweeps/house.glb");
    EXPECT_EQ(c.models[1].path, "/data/fzk.ifc");
    EXPECT_EQ(c.models[2].sample, "manual");
    EXPECT_TRUE(c.models[2].path.empty());
    EXPECT_EQ(c.level_modes, (std::vector<LevelMode>{LevelMode::top_down, LevelMode::box_volume}));
    EXPECT_EQ(c.box_kinds, (std::vector<BoxKind>{BoxKind::expanded, BoxKind::minimal}));
    EXPECT_EQ(c.interpolations, (std::vector<Interpolation>{Interpolation::linear, Interpolation::rank}));
    EXPECT_EQ(c.levels, (std::vector<int>{0, 1, 3}));
    EXPECT_EQ(c.lod.wanted_levels, 5);
    EXPECT_EQ(c.views, (std::vector<std::string>{"+X+Y+Z", "-Z"}));
    EXPECT_EQ(c.distances, (std::vector<float>{1, 2.5f}));
    EXPECT_EQ(c.render_modes, (std::vector<RenderMode>{RenderMode::normal, RenderMode::parallax}));
    EXPECT_EQ(c.width, 64);
    EXPECT_EQ(c.height, 48);
    EXPECT_EQ(c.lod.fovy, 30);
    EXPECT_EQ(c.metrics, (std::vector<Metric>{Metric::psnr, Metric::ssim}));
    EXPECT_EQ(c.pixels_per_degree, 40);
    EXPECT_EQ(c.supersampling, 2);
    EXPECT_EQ(SweepConfig{}.supersampling, 1);
    EXPECT_EQ(c.lod.resolution, 256);
    EXPECT_EQ(c.keep_images, KeptImages::all);
    EXPECT_EQ(c.threads, 2);
    EXPECT_EQ(c.sizing, SizingRule::each_distance);
    EXPECT_EQ(c.baselines, (std::vector<Baseline>{Baseline::single_box, Baseline::simplification}));
    EXPECT_TRUE(c.lod.keep_small_subtrees);
    EXPECT_FALSE(c.lod.keep_cheaper_subtrees);
}

TEST(SweepConfig, AllMeansEveryViewAndEveryLevel) {
    SweepConfig c = parse_sweep_config("models = a.glb\nviews = all\nlevels = all\n", "c.txt");
    EXPECT_EQ(c.views, camera_position_names());
    EXPECT_EQ(c.views.size(), 26u);
    EXPECT_TRUE(c.levels.empty());
    EXPECT_EQ(c.metrics.size(), 6u);             // default: every metric
    EXPECT_EQ(c.sizing, SizingRule::per_level);  // the chain that pays its way
    EXPECT_TRUE(c.lod.keep_cheaper_subtrees);
    EXPECT_TRUE(c.baselines.empty());
    // manual = true: the manual's one sizing distance and cut; keys after it change single settings.
    SweepConfig manual = parse_sweep_config("models = a.glb\nmanual = true\nflat_faces = 4\n", "c.txt");
    EXPECT_EQ(manual.sizing, SizingRule::nearest);
    EXPECT_FALSE(manual.lod.keep_cheaper_subtrees);
    EXPECT_EQ(manual.lod.min_texture_size, 256);
    EXPECT_EQ(manual.lod.flat_faces, 4);
    SweepConfig none = parse_sweep_config("models = a.glb\nbaselines = none\n", "c.txt");
    EXPECT_TRUE(none.baselines.empty());
    SweepConfig best =
        parse_sweep_config("models = a.glb\nbaselines = simplification-best, simplification\n", "c.txt");
    EXPECT_EQ(best.baselines,
              (std::vector<Baseline>{Baseline::simplification_best, Baseline::simplification}));
    SweepConfig impostor =
        parse_sweep_config("models = a.glb\nbaselines = impostor\nimpostor_directions = 12\n", "c.txt");
    EXPECT_EQ(impostor.baselines, (std::vector<Baseline>{Baseline::impostor}));
    EXPECT_EQ(impostor.impostor_directions, 12);
    EXPECT_EQ(none.impostor_directions, 8);
}

// The message names the file, the line and the key.
void expect_error(const std::string& text, const std::string& expected) {
    try {
        parse_sweep_config(text, "cfg.txt");
        ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
}

// A range's ends are in it, a float's too (0.01 as a float lies below 0.01); repeats count once.
TEST(SweepConfig, DistancesTakeTheirRangesEndsOnceEach) {
    SweepConfig c = parse_sweep_config("models = a.glb\ndistances = 0.01, 1000, 2, 0.01, 2\n", "c.txt");
    EXPECT_EQ(c.distances, std::vector<float>({0.01f, 1000, 2}));
}

TEST(SweepConfig, ErrorsNameFileLineAndKey) {
    expect_error("models = a.glb\nfrobnicate = 1\n", "cfg.txt: line 2: frobnicate: unknown key");
    expect_error("models = a.glb\n\nlevel_modes = top-down, sideways\n",
                 "cfg.txt: line 3: level_modes: unknown value 'sideways'");
    expect_error("models = a.glb\nviews = +X, +W\n", "cfg.txt: line 2: views: unknown camera position '+W'");
    expect_error("models = a.glb\nviews = all, all\n",
                 "cfg.txt: line 2: views: 'all' stands alone: it names every camera position");
    expect_error("models = a.glb\nwidth = wide\n", "cfg.txt: line 2: width: expected a number");
    expect_error("models = a.glb\nwidth = 256.5\n",
                 "cfg.txt: line 2: width: expected a whole number in [16, 16384], got '256.5'");
    expect_error("models = a.glb\nwidth = 4\n",
                 "cfg.txt: line 2: width: expected a number in [16, 16384], got '4'");
    expect_error("models = a.glb\ndistances = 1, -2\n",
                 "cfg.txt: line 2: distances: expected a number in [0.01, 1000], got '-2'");
    expect_error("models = a.glb\nsupersampling = 8\n",
                 "cfg.txt: line 2: supersampling: expected a number in [1, 4], got '8'");
    expect_error("models = a.glb\nppd = 1e8\n",
                 "cfg.txt: line 2: ppd: expected a number in [1, 300], got '1e8'");
    expect_error("models = a.glb\nwanted_levels = 1000000000\n",
                 "cfg.txt: line 2: wanted_levels: expected a number in [1, 64]");
    expect_error("models = a.glb\nlevels = 1,,2\n", "cfg.txt: line 2: levels: empty item");
    expect_error(
        "models = a.glb\nmetrics = psnr, vmaf\n",
        "cfg.txt: line 2: metrics: unknown value 'vmaf' (rmse, psnr, ssim, flip, flip_covered, iou)");
    expect_error("models = a.glb\nkeep_images = some\n",
                 "cfg.txt: line 2: keep_images: expected none, lod or all");
    expect_error("models = a.glb\nmin_texture_size = 100\n",
                 "cfg.txt: line 2: min_texture_size: expected a power of two in [1, 16384], got '100'");
    expect_error("models = a.glb\nmin_texture_size = 8192\n",
                 "cfg.txt: min_texture_size and max_texture_size must be powers of two");
    expect_error("models = a.glb\nlevel_mode = top-down\n",
                 "cfg.txt: line 2: level_mode: the sweep varies this itself");
    expect_error("models = a.glb\nkeep_small_subtrees = yes\n",
                 "cfg.txt: line 2: keep_small_subtrees: expected true or false");
    expect_error("models = a.glb\nsizing = far\n",
                 "cfg.txt: line 2: sizing: expected nearest, each-distance or per-level");
    expect_error("models = a.glb\nbaselines = qem\n",
                 "cfg.txt: line 2: baselines: unknown value 'qem' (simplification, simplification-best, "
                 "cgal, single-box, impostor, proxy-baked, file-lods)");
    expect_error("models = a.glb\nimpostor_directions = 64\n", "cfg.txt: line 2: impostor_directions: ");
    expect_error("models = a.glb\nmodels = b.glb\n",
                 "cfg.txt: line 2: models: given twice (first on line 1)");
    expect_error("models = a.glb\nthreads =\n", "cfg.txt: line 2: threads: missing value");
    expect_error("models = a.glb\njust words\n", "cfg.txt: line 2: expected 'key = value'");
    expect_error("models = sample:\n", "cfg.txt: line 1: models: 'sample:' needs a sample name");
    expect_error("models = a.glb, sample:house, ./a.glb\n",
                 "cfg.txt: line 1: models: './a.glb' is the model 'a.glb' again");
    expect_error("models = sample:house, sample:house\n",
                 "cfg.txt: line 1: models: 'sample:house' is the model 'sample:house' again");
    expect_error("width = 64\n", "cfg.txt: no models");
    // As build refuses them: budgets with no mode that takes them would sweep nothing of theirs.
    expect_error("models = a.glb\nlevel_modes = top-down, box-area\nbudgets = 0.5\n",
                 "cfg.txt: budgets: no level mode of level_modes orders its cuts by bytes");
    EXPECT_NO_THROW(
        parse_sweep_config("models = a.glb\nlevel_modes = top-down, hybrid\nbudgets = 0.5\n", "cfg.txt"));
}

TEST(SweepConfig, LoadNamesAMissingFile) {
    auto folder = test::scratch_folder("sweep_config_load");
    EXPECT_THROW(load_sweep_config((folder / "nope.txt").string()), InputError);
    test::write_text(folder / "ok.txt", "models = m.glb\n");
    SweepConfig c = load_sweep_config((folder / "ok.txt").string());
    EXPECT_EQ(c.models.at(0).path, (folder / "m.glb").lexically_normal().string());
}

// The most rows a sweep can make, before any model is read: per model (2),
// variants (2 level modes) and baselines (1), each at every level (wanted 8,
// or the 4 budgets, and level 0), times views (3), distances (2) and modes (1).
TEST(SweepConfig, MostRowsBoundTheCrossProductBeforeAModelIsRead) {
    const std::string lists =
        "models = a.glb, b.glb\nlevel_modes = top-down, hybrid\nbaselines = simplification\n"
        "views = +X, -X, +Z\ndistances = 1, 2\n";
    EXPECT_EQ(most_sweep_rows(parse_sweep_config(lists, "c.txt")), 2.0 * 3 * 9 * 6);
    EXPECT_EQ(most_sweep_rows(parse_sweep_config(
                  lists + "budgets = 0.5, 0.1, 0.01, 0.001\nwanted_levels = 2\n", "c.txt")),
              2.0 * 3 * 5 * 6);
    EXPECT_EQ(most_sweep_rows(parse_sweep_config(lists + "levels = 0, 3\n", "c.txt")), 2.0 * 3 * 2 * 6);
}

// The configs the README and docs point to load as shipped (their models exist once make test has installed
// them).
TEST(SweepConfig, EveryShippedConfigLoads) {
    const std::filesystem::path configs =
        std::filesystem::path(BOXLOD_TEST_DATA).parent_path().parent_path() / "experiments" / "configs";
    int loaded = 0;
    for (const auto& entry : std::filesystem::directory_iterator(configs)) {
        if (entry.path().extension() != ".txt") continue;
        EXPECT_NO_THROW(load_sweep_config(entry.path().string())) << entry.path();
        ++loaded;
    }
    EXPECT_GE(loaded, 4);  // demo, manual_sweep, render_modes, smoke
}

}  // namespace
}  // namespace boxlod
