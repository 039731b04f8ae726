#include "experiments/sweep/sweep.h"

#include "base/input_error.h"
#include "experiments/sweep/proxy_baked.h"
#include "lod_scene.h"
#include "test_support.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/hybrid/simplification.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

#include <functional>
#include <sstream>

namespace boxlod {
namespace {

using Table = std::vector<std::vector<std::string>>;  // header first

Table read_csv(const std::filesystem::path& path) {
    Table table;
    std::istringstream in(test::read_text(path));
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string>& row = table.emplace_back();
        std::stringstream fields(line);
        for (std::string field; std::getline(fields, field, ',');) row.push_back(field);
    }
    return table;
}

std::size_t column(const Table& table, const std::string& name) {
    auto found = std::find(table[0].begin(), table[0].end(), name);
    EXPECT_NE(found, table[0].end()) << name;
    return std::size_t(found - table[0].begin());
}

// The hand-built building saved beside a config: 2 level modes x levels 0 and 4
// (its top, one box) x 2 views, 64x48.
struct SmallSweep {
    std::filesystem::path folder;
    SweepConfig config;
    MeshCounts original;
    ModelCost original_cost;
};

SmallSweep small_sweep(const std::string& name, const std::string& extra = "") {
    SmallSweep s;
    s.folder = test::scratch_folder(name);
    Model building = test::lod_test_building();
    s.original = mesh_counts(building);
    s.original_cost = model_cost(building);
    save_model(building, (s.folder / "building.glb").string());
    test::write_text(s.folder / "sweep.txt",
                     // The manual's program: the test building's small parts are boxed too.
                     "manual = true\nmodels = building.glb\nlevel_modes = top-down, bottom-up\nlevels = 0, "
                     "4\nviews = +X+Y+Z, -Z\n"
                     "width = 64\nheight = 48\nmetrics = rmse, psnr, ssim, flip, iou\nresolution = 48\n" +
                         extra);
    s.config = load_sweep_config((s.folder / "sweep.txt").string());
    return s;
}

TEST(Sweep, RowsCountsAndMetricsOfTheCrossProduct) {
    SmallSweep s = small_sweep("sweep_rows", "keep_images = lod\n");
    SweepReport report = run_sweep(s.config, (s.folder / "out").string(), 1);
    EXPECT_EQ(report.rows, 8u);
    EXPECT_EQ(report.rows_computed, 8u);
    EXPECT_EQ(report.rows_skipped, 0u);
    EXPECT_EQ(report.lods_built, 4u);
    EXPECT_EQ(report.lod_renders, 8u);
    EXPECT_EQ(report.original_renders, 2u);  // once per view, shared by every LoD

    Table t = read_csv(s.folder / "out" / "results.csv");
    ASSERT_EQ(t.size(), 9u);
    EXPECT_EQ(t[0], result_columns(s.config));
    std::size_t mode = column(t, "level_mode"), level = column(t, "level"), view = column(t, "view"),
                faces = column(t, "faces"), psnr = column(t, "psnr"), ssim = column(t, "ssim"),
                rmse = column(t, "rmse"), flip = column(t, "flip"), iou = column(t, "iou"),
                obtained = column(t, "obtained_levels"), texels = column(t, "texels");
    // The cross product's order: mode, level, then view.
    EXPECT_EQ(t[1][mode], "top-down");
    EXPECT_EQ(t[1][level], "0");
    EXPECT_EQ(t[1][view], "+X+Y+Z");
    EXPECT_EQ(t[2][view], "-Z");
    EXPECT_EQ(t[3][level], "4");
    EXPECT_EQ(t[5][mode], "bottom-up");
    for (std::size_t r = 1; r < t.size(); ++r) {
        ASSERT_EQ(t[r].size(), t[0].size());
        EXPECT_EQ(t[r][obtained], "4");
        if (t[r][level] == "0") {  // the original itself
            EXPECT_EQ(t[r][psnr], "inf");
            EXPECT_EQ(t[r][ssim], "1");
            EXPECT_EQ(t[r][rmse], "0");
            EXPECT_EQ(t[r][flip], "0");
            EXPECT_EQ(t[r][iou], "1");
            EXPECT_EQ(t[r][faces], std::to_string(s.original.faces));
            EXPECT_EQ(t[r][texels], "0");
        } else {  // one box
            EXPECT_EQ(t[r][faces], "6");
            EXPECT_NE(t[r][psnr], "inf");
            EXPECT_LT(std::stod(t[r][ssim]), 1);
            EXPECT_GT(std::stod(t[r][texels]), 0);
        }
    }
    Table timings = read_csv(s.folder / "out" / "timings.csv");
    ASSERT_EQ(timings.size(), 9u);
    EXPECT_EQ(timings[0], timing_columns());
    for (std::size_t r = 1; r < t.size(); ++r)
        EXPECT_TRUE(std::equal(t[r].begin(), t[r].begin() + 8, timings[r].begin())) << r;
    auto images = s.folder / "out" / "images";
    EXPECT_TRUE(std::filesystem::exists(images / "building.glb_top-down_expanded_linear_4_-Z_1_normal.png"));
    EXPECT_TRUE(std::filesystem::exists(images / "building.glb_original_-Z_1_normal.png"));
}

std::vector<std::string> row_of(const Table& table, const std::string& prefix) {
    for (std::size_t r = 1; r < table.size(); ++r) {
        std::string line;
        for (const std::string& field : table[r]) line += field + ",";
        if (line.starts_with(prefix)) return table[r];
    }
    ADD_FAILURE() << "no row " << prefix;
    return table[0];
}

// Kept images are named after the model's name made a file name: x/t.glb and x_t.glb wrote over each
// other's, and the sweep said nothing; now it is refused before any folder is made.
TEST(Sweep, ModelsWhoseKeptImagesWouldShareNamesAreRefused) {
    SmallSweep s = small_sweep("sweep_image_names", "keep_images = lod\n");
    std::filesystem::create_directories(s.folder / "x");
    std::filesystem::copy_file(s.folder / "building.glb", s.folder / "x" / "t.glb");
    std::filesystem::copy_file(s.folder / "building.glb", s.folder / "x_t.glb");
    s.config.models = {{"x/t.glb", (s.folder / "x" / "t.glb").string(), ""},
                       {"x_t.glb", (s.folder / "x_t.glb").string(), ""}};
    EXPECT_EQ(test::input_error_of([&] { run_sweep(s.config, (s.folder / "out").string(), 1); }),
              "keep_images: models 'x/t.glb' and 'x_t.glb' would write the same image files: rename one");
    EXPECT_FALSE(std::filesystem::exists(s.folder / "out"));
    s.config.keep_images = KeptImages::none;
    run_sweep(s.config, (s.folder / "out").string(), 1);  // without images the names may meet
}

// The baselines come after the LoD rows: a simplified mesh per level of the first level
// mode, at that level's triangles (never above), and the single box at its top.
TEST(Sweep, BaselinesFollowTheFirstLevelModesTriangles) {
    SmallSweep s = small_sweep("sweep_baselines", "baselines = simplification, single-box\n");
    SweepReport report = run_sweep(s.config, (s.folder / "out").string(), 2);
    EXPECT_EQ(report.rows, 8u + 4u + 2u);  // LoDs, simplification at levels 0 and 4, single box
    EXPECT_EQ(report.lods_built, 4u + 2u + 1u);
    Table t = read_csv(s.folder / "out" / "results.csv");
    ASSERT_EQ(t.size(), 15u);
    std::size_t triangles = column(t, "triangles"), faces = column(t, "faces"), ssim = column(t, "ssim"),
                texels = column(t, "texels"), level = column(t, "level");
    EXPECT_EQ(t[9][column(t, "level_mode")], "simplification");
    EXPECT_EQ(t[13][column(t, "level_mode")], "single-box");
    EXPECT_EQ(t[13][level], "4");
    EXPECT_EQ(t[13][column(t, "box_kind")], "-");
    for (const char* view : {"+X+Y+Z,", "-Z,"}) {
        auto original = row_of(t, std::string("building.glb,simplification,-,-,0,") + view);
        EXPECT_EQ(original[triangles], std::to_string(s.original.triangles));
        EXPECT_EQ(original[ssim], "1");
        // Every row states its cost; simplification at level 0 is the original, textures and all.
        EXPECT_EQ(original[column(t, "bytes")], std::to_string(s.original_cost.bytes()));
        EXPECT_EQ(original[column(t, "draw_calls")], std::to_string(s.original_cost.draw_calls));
        auto box = row_of(t, std::string("building.glb,top-down,expanded,linear,4,") + view);
        EXPECT_GT(std::stoull(box[column(t, "texture_bytes_gpu")]), 0u);
        EXPECT_EQ(box[column(t, "draw_calls")], "1");
        // The proxy error of a level: 0 at the original, its box's at the top; none for a baseline.
        EXPECT_EQ(row_of(t, std::string("building.glb,top-down,expanded,linear,0,") +
                                view)[column(t, "depth_error")],
                  "0");
        EXPECT_GT(std::stod(box[column(t, "depth_error")]), 0);
        auto simplified = row_of(t, std::string("building.glb,simplification,-,-,4,") + view);
        EXPECT_EQ(simplified[column(t, "depth_error")], "");
        EXPECT_LE(std::stoul(simplified[triangles]), std::stoul(box[triangles]));
        EXPECT_GT(std::stoul(simplified[triangles]), 0u);
        EXPECT_EQ(simplified[faces], simplified[triangles]);
        EXPECT_EQ(simplified[texels], "0");
        auto single = row_of(t, std::string("building.glb,single-box,-,-,4,") + view);
        EXPECT_EQ(single[faces], "6");
        EXPECT_EQ(single[column(t, "texture_bytes")], "0");
        EXPECT_EQ(single[column(t, "mesh_bytes")], single[column(t, "bytes")]);
        EXPECT_LT(std::stod(single[ssim]), 1);
    }
}

// A row pays for the maps its render mode draws: the same boxes cost their
// height pages (BC4, 8 of the 32 bytes per block of BC1 colour + BC5 normal +
// BC4 height) under parallax and not under normal mapping.
TEST(Sweep, EachRowPaysForTheMapsItsRenderModeDraws) {
    SmallSweep s = small_sweep("sweep_mode_cost", "render_modes = normal, parallax\n");
    run_sweep(s.config, (s.folder / "out").string(), 2);
    Table t = read_csv(s.folder / "out" / "results.csv");
    const std::size_t gpu = column(t, "texture_bytes_gpu"), bytes = column(t, "bytes"),
                      mesh = column(t, "mesh_bytes");
    auto row = [&](const std::string& level, const std::string& mode) {
        return row_of(t, "building.glb,top-down,expanded,linear," + level + ",+X+Y+Z,1," + mode);
    };
    const auto normal = row("4", "normal"), parallax = row("4", "parallax");
    const std::uint64_t normal_gpu = std::stoull(normal[gpu]), parallax_gpu = std::stoull(parallax[gpu]);
    EXPECT_GT(normal_gpu, 0u);
    EXPECT_EQ(parallax_gpu - normal_gpu, parallax_gpu / 4);
    EXPECT_EQ(normal[mesh], parallax[mesh]);
    EXPECT_EQ(std::stoull(normal[bytes]), std::stoull(normal[mesh]) + normal_gpu);
    // The original has no height maps: the same cost in both modes, as it states.
    EXPECT_EQ(row("0", "normal")[bytes], std::to_string(s.original_cost.bytes()));
    EXPECT_EQ(row("0", "parallax")[bytes], std::to_string(s.original_cost.bytes()));
}

// simplification-best draws every meshoptimizer variant and keeps, per level, the one
// with the lowest mean FLIP over the views: never worse than plain simplification
// (its `collapse` variant), never above the level's triangles, and named in its rows;
// cgal rows follow it, named too.
TEST(Sweep, SimplificationBestKeepsTheVariantWithTheLowestError) {
    SmallSweep s = small_sweep("sweep_best", "baselines = simplification-best, cgal, simplification\n");
    SweepReport report = run_sweep(s.config, (s.folder / "out").string(), 2);
    EXPECT_EQ(report.rows, 8u + 4u + 4u + 4u);
    EXPECT_EQ(report.lods_built, 4u + 2u + 2u * simplify_variants(1).size() + 2u);
    Table t = read_csv(s.folder / "out" / "results.csv");
    const std::size_t flip = column(t, "flip"), variant = column(t, "baseline_variant"),
                      triangles = column(t, "triangles");
    EXPECT_EQ(t[9][column(t, "level_mode")], "simplification");  // the table's order, not the config's
    EXPECT_EQ(t[13][column(t, "level_mode")], "simplification-best");
    EXPECT_EQ(t[17][column(t, "level_mode")], "cgal");
    for (std::size_t r = 1; r < 9; ++r) EXPECT_EQ(t[r][variant], "") << r;
    for (const char* level : {"0,", "4,"}) {
        double plain = 0, best = 0;
        std::string chosen;
        for (const char* view : {"+X+Y+Z,", "-Z,"}) {
            auto p = row_of(t, std::string("building.glb,simplification,-,-,") + level + view);
            auto b = row_of(t, std::string("building.glb,simplification-best,-,-,") + level + view);
            auto box = row_of(t, std::string("building.glb,top-down,expanded,linear,") + level + view);
            EXPECT_EQ(p[variant], "collapse");
            EXPECT_TRUE(b[variant] == "collapse" || b[variant] == "lock-border" || b[variant] == "sloppy")
                << b[variant];
            if (chosen.empty()) chosen = b[variant];
            EXPECT_EQ(b[variant], chosen);  // one mesh for every view of a level
            EXPECT_LE(std::stoul(b[triangles]), std::stoul(box[triangles]));
            plain += std::stod(p[flip]);
            best += std::stod(b[flip]);
            auto cgal = row_of(t, std::string("building.glb,cgal,-,-,") + level + view);
            EXPECT_EQ(cgal[variant], "garland-heckbert");
            EXPECT_GT(std::stoul(cgal[triangles]), 0u);
        }
        EXPECT_LE(best, plain) << level;
    }
}

// proxy-baked: per level the model's geometry simplified as one mesh and drawn
// with its root box's baked pages, as finely as the level's budget allows, the
// variant with the lowest error kept (one for every view of a level, named).
// Nothing that draws fits 10 % of the small test building: that level draws
// the cheapest that does, over its budget as its bytes say.
TEST(Sweep, ProxyBakedDrawsTheSimplifiedModelOnItsBakedBoxWithinEachBudget) {
    const std::filesystem::path folder = test::scratch_folder("sweep_proxy_baked");
    const Model building = test::lod_test_building();
    save_model(building, (folder / "building.glb").string());
    test::write_text(folder / "sweep.txt",
                     "models = building.glb\nlevel_modes = error-greedy\nbudgets = 0.9, 0.1\n"
                     "baselines = proxy-baked\nviews = +X+Y+Z, -Z\nwidth = 64\nheight = 48\n"
                     "metrics = flip\nresolution = 48\n");
    const SweepReport report =
        run_sweep(load_sweep_config((folder / "sweep.txt").string()), (folder / "out").string(), 2);
    EXPECT_EQ(report.rows, 6u + 4u);  // no level 0: a baked copy of the original is no level
    Table t = read_csv(folder / "out" / "results.csv");
    const std::size_t variant = column(t, "baseline_variant"), bytes = column(t, "bytes"),
                      pages = column(t, "pages"), triangles = column(t, "triangles");
    std::vector<std::string> names;
    for (const ProxyBakedVariant& v : proxy_baked_variants(1)) names.push_back(v.name);
    const double original = double(model_cost(building).bytes());
    for (const auto& [level, budget] : {std::pair{"1,", 0.9}, std::pair{"2,", 0.1}}) {
        std::string chosen;
        for (const char* view : {"+X+Y+Z,", "-Z,"}) {
            auto row = row_of(t, std::string("building.glb,proxy-baked,-,-,") + level + view);
            EXPECT_NE(std::find(names.begin(), names.end(), row[variant]), names.end()) << row[variant];
            if (chosen.empty()) chosen = row[variant];
            EXPECT_EQ(row[variant], chosen);
            if (budget == 0.9) {
                EXPECT_LE(std::stod(row[bytes]), budget * original);
            }
            EXPECT_GE(std::stoi(row[pages]), 1) << level;  // its colours are baked
            EXPECT_GT(std::stoi(row[triangles]), 0) << level;
        }
    }
}

// The impostor: one atlas for the model, a quad per view facing the captured direction
// nearest its camera; 2 triangles, 1 draw call, the whole atlas in its bytes.
TEST(Sweep, ImpostorDrawsOneQuadPerViewFromOneAtlas) {
    SmallSweep s = small_sweep("sweep_impostor", "baselines = impostor\nimpostor_directions = 4\n");
    SweepReport report = run_sweep(s.config, (s.folder / "out").string(), 2);
    EXPECT_EQ(report.rows, 8u + 2u);
    EXPECT_EQ(report.lods_built, 4u + 2u);  // a quad per view
    Table t = read_csv(s.folder / "out" / "results.csv");
    std::string variants;
    for (const char* view : {"+X+Y+Z,", "-Z,"}) {
        auto row = row_of(t, std::string("building.glb,impostor,-,-,4,") + view);
        EXPECT_EQ(row[column(t, "triangles")], "2");
        EXPECT_EQ(row[column(t, "draw_calls")], "1");
        EXPECT_GT(std::stoull(row[column(t, "texture_bytes_gpu")]), 0u);
        EXPECT_EQ(row[column(t, "baseline_variant")].rfind("direction ", 0), 0u);
        EXPECT_GT(std::stod(row[column(t, "ssim")]), 0.5);
        variants += row[column(t, "baseline_variant")] + ";";
    }
    EXPECT_NE(variants, "direction 0;direction 0;");  // +X+Y+Z and -Z are seen from different cells
}

// A CityJSON district's objects (FILE#*), each against its own coarser LoDs
// read from the same file: two blocks at LoD 1.2 under gabled houses at 2.2.
TEST(Sweep, FileLodsAreEachObjectsOwnCoarserLevels) {
    const std::filesystem::path folder = test::scratch_folder("sweep_file_lods");
    ASSERT_EQ(
        std::system(("/usr/bin/python3 " + std::string(BOXLOD_TEST_DATA) +
                     "/../end_to_end/make_district.py " + (folder / "district.city.json").string() + " 2")
                        .c_str()),
        0);
    test::write_text(
        folder / "sweep.txt",
        "models = district.city.json#*\nlevel_modes = top-down\nlevels = 0\nviews = +X+Y+Z\nwidth = 64\n"
        "height = 48\nmetrics = flip\nresolution = 48\nbaselines = file-lods\n");
    const SweepConfig config = load_sweep_config((folder / "sweep.txt").string());
    ASSERT_EQ(config.models.size(), 2u);
    EXPECT_EQ(config.models[1].name, "district.city.json#house_1");
    SweepReport report = run_sweep(config, (folder / "out").string(), 2);
    EXPECT_EQ(report.rows, 4u);  // per house: its level 0 and its LoD 1.2
    Table t = read_csv(folder / "out" / "results.csv");
    for (const char* house : {"house_0", "house_1"}) {
        const auto original =
            row_of(t, std::string("district.city.json#") + house + ",top-down,expanded,linear,0,");
        const auto rival = row_of(t, std::string("district.city.json#") + house + ",file-lods,-,-,1,");
        EXPECT_EQ(rival[column(t, "baseline_variant")], "LoD 1.2");
        EXPECT_LT(std::stoull(rival[column(t, "triangles")]),
                  std::stoull(original[column(t, "triangles")]));  // a block, no roof
        EXPECT_GT(std::stod(rival[column(t, "flip")]), 0);
    }
}

// each-distance bakes an LoD per distance: four times the distance, about a sixteenth
// of the texels; nearest draws the texels of the smallest distance everywhere.
TEST(Sweep, SizingEachDistanceBakesFewerTexelsFartherAway) {
    SmallSweep each = small_sweep("sweep_sizing_each", "sizing = each-distance\n");
    each.config.levels = {4};
    each.config.views = {"+X+Y+Z"};
    each.config.distances = {1, 4};
    each.config.level_modes = {LevelMode::top_down};
    SweepConfig nearest = each.config;
    nearest.sizing = SizingRule::nearest;
    run_sweep(each.config, (each.folder / "each").string(), 1);
    run_sweep(nearest, (each.folder / "nearest").string(), 1);
    for (const char* folder : {"each", "nearest"}) {
        Table t = read_csv(each.folder / folder / "results.csv");
        ASSERT_EQ(t.size(), 3u);
        double near_texels = std::stod(t[1][column(t, "face_texels")]),
               far_texels = std::stod(t[2][column(t, "face_texels")]);
        EXPECT_GT(near_texels, 0);
        if (std::string(folder) == "each") {
            EXPECT_LT(far_texels, near_texels / 8)
                << "a quarter of the texels per side, give or take rounding up";
        } else {
            EXPECT_EQ(far_texels, near_texels);
        }
    }
}

// per-level sizing: level c baked for the nearest distance x 2^(c-1), as `build --level-distances auto`.
TEST(Sweep, SizingPerLevelBakesCoarserLevelsForFartherAway) {
    SmallSweep s = small_sweep("sweep_sizing_per_level", "sizing = per-level\nmin_texture_size = 16\n");
    s.config.levels = {1, 3};
    s.config.views = {"+X+Y+Z"};
    s.config.level_modes = {LevelMode::top_down};
    EXPECT_EQ(s.config.lod.min_texture_size, 16);
    SweepConfig nearest = s.config;
    nearest.sizing = SizingRule::nearest;
    run_sweep(s.config, (s.folder / "per_level").string(), 1);
    run_sweep(nearest, (s.folder / "nearest").string(), 1);
    Table per_level = read_csv(s.folder / "per_level" / "results.csv"),
          one = read_csv(s.folder / "nearest" / "results.csv");
    ASSERT_EQ(per_level.size(), 3u);
    ASSERT_EQ(one.size(), 3u);
    const std::size_t texels = column(one, "face_texels"), covered = column(one, "covered_pixels");
    EXPECT_EQ(per_level[1][texels], one[1][texels]);  // level 1: the nearest distance itself
    EXPECT_LT(std::stod(per_level[2][texels]), std::stod(one[2][texels]) / 8) << "level 3: 4x farther";
    // The original's covered pixels are the view's, whatever the LoD.
    EXPECT_GT(std::stod(one[1][covered]), 0);
    EXPECT_EQ(per_level[1][covered], one[2][covered]);
}

// Two threads draw two rows at a time, each on one thread (draw_rows); one
// thread draws them one by one: the same pixels, heat maps and metrics.
TEST(Sweep, ResultsAndImagesAreIdenticalForOneAndTwoThreads) {
    SmallSweep s = small_sweep("sweep_threads", "keep_images = all\n");
    run_sweep(s.config, (s.folder / "one").string(), 1);
    run_sweep(s.config, (s.folder / "two").string(), 2);
    std::string one = test::read_text(s.folder / "one" / "results.csv");
    EXPECT_GT(one.size(), 100u);
    EXPECT_EQ(one, test::read_text(s.folder / "two" / "results.csv"));
    std::size_t images = 0;
    for (const auto& entry : std::filesystem::directory_iterator(s.folder / "one" / "images")) {
        EXPECT_EQ(test::read_text(entry.path()),
                  test::read_text(s.folder / "two" / "images" / entry.path().filename()))
            << entry.path().filename();
        ++images;
    }
    EXPECT_EQ(images, 2u * 2u * 2u * 2u +
                          2u);  // level modes x levels x views, a heat map each; the original per view
}

TEST(Sweep, ResumingFillsInOnlyTheMissingRows) {
    SmallSweep s = small_sweep("sweep_resume");
    auto out = s.folder / "out";
    run_sweep(s.config, out.string(), 2);
    std::string full = test::read_text(out / "results.csv");

    // Delete one whole group (bottom-up level 4) and one row of another (top-down level 0, -Z).
    std::istringstream in(full);
    std::string kept;
    int deleted = 0;
    for (std::string line; std::getline(in, line);) {
        bool drop = line.starts_with("building.glb,bottom-up,expanded,linear,4,") ||
                    line.starts_with("building.glb,top-down,expanded,linear,0,-Z,");
        deleted += drop;
        if (!drop) kept += line + "\n";
    }
    ASSERT_EQ(deleted, 3);
    test::write_text(out / "results.csv", kept);

    SweepReport report = run_sweep(s.config, out.string(), 1);
    EXPECT_EQ(report.rows_computed, 3u);
    EXPECT_EQ(report.rows_skipped, 5u);
    EXPECT_EQ(report.lods_built, 2u);
    EXPECT_EQ(report.lod_renders, 3u);
    EXPECT_EQ(test::read_text(out / "results.csv"), full);

    SweepReport again = run_sweep(s.config, out.string(), 1);  // nothing left to do
    EXPECT_EQ(again.rows_computed, 0u);
    EXPECT_EQ(again.lods_built, 0u);
    EXPECT_EQ(again.original_renders, 0u);
    EXPECT_EQ(test::read_text(out / "results.csv"), full);
}

// Two models x two level modes, with a baseline: four shards, run apart and
// merged, give the whole sweep's results.csv byte for byte.
TEST(Sweep, ShardsMergeIntoTheWholeSweepsBytes) {
    SmallSweep s = small_sweep("sweep_shards", "baselines = simplification\n");
    std::filesystem::copy_file(s.folder / "building.glb", s.folder / "second.glb");
    std::string text = test::read_text(s.folder / "sweep.txt");
    text.replace(text.find("models = building.glb"), 21, "models = building.glb, second.glb");
    test::write_text(s.folder / "sweep.txt", text);
    SweepConfig config = load_sweep_config((s.folder / "sweep.txt").string());
    ASSERT_EQ(config.models.size(), 2u);
    run_sweep(config, (s.folder / "whole").string(), 2);
    const std::string whole = test::read_text(s.folder / "whole" / "results.csv");

    const std::vector<SweepShard> shards = sweep_shards(config);
    ASSERT_EQ(shards.size(), 4u);
    EXPECT_EQ(shards[1].model, 0u);
    EXPECT_EQ(shards[1].level_mode, LevelMode::bottom_up);
    EXPECT_EQ(shard_config(config, shards[0]).baselines.size(),
              1u);  // the baselines follow the first level mode
    EXPECT_TRUE(shard_config(config, shards[1]).baselines.empty());
    std::size_t rows = 0;
    for (std::size_t k = 0; k < shards.size(); ++k) {
        const auto folder = s.folder / "shards" / std::to_string(k);
        rows += run_sweep(shard_config(config, shards[k]), folder.string(), 1).rows;
    }
    EXPECT_EQ(
        rows,
        2u * (8 + 4));  // per model: 2 modes x 2 levels x 2 views, and the baseline's 2 levels x 2 views

    // Merged in any order of the shards: the same bytes, nothing computed again.
    const std::vector<std::string> folders{
        (s.folder / "shards" / "3").string(), (s.folder / "shards" / "0").string(),
        (s.folder / "shards" / "2").string(), (s.folder / "shards" / "1").string()};
    SweepReport merged = merge_sweep(config, folders, (s.folder / "merged").string(), 2);
    EXPECT_EQ(merged.rows_computed, 0u);
    EXPECT_EQ(merged.lods_built, 0u);
    EXPECT_EQ(test::read_text(s.folder / "merged" / "results.csv"), whole);

    // A missing shard is computed by the merge (resuming); a shard that disagrees is refused.
    SweepReport resumed =
        merge_sweep(config, {folders[0], folders[1], folders[2]}, (s.folder / "resumed").string(), 2);
    EXPECT_EQ(resumed.rows_computed, 4u);
    EXPECT_EQ(test::read_text(s.folder / "resumed" / "results.csv"), whole);
    std::string changed = test::read_text(s.folder / "shards" / "1" / "results.csv");
    changed.insert(changed.rfind(',') + 1, "9");
    test::write_text(s.folder / "shards" / "1" / "results.csv", changed);
    EXPECT_THROW(merge_sweep(config, folders, (s.folder / "merged").string(), 2), InputError);

    EXPECT_EQ(parse_sweep_shard(config, "2:bottom-up").model, 1u);
    EXPECT_THROW(parse_sweep_shard(config, "3:top-down"), InputError);
    EXPECT_THROW(parse_sweep_shard(config, "1:box-area"), InputError);  // not one of the config's modes
    EXPECT_THROW(parse_sweep_shard(config, "1"), InputError);
    EXPECT_THROW(parse_sweep_shard(config, "0:top-down"), InputError);
}

TEST(Sweep, RefusesAResultsFileWithOtherColumns) {
    SmallSweep s = small_sweep("sweep_columns");
    std::filesystem::create_directories(s.folder / "out");
    test::write_text(s.folder / "out" / "results.csv", "model,level_mode,psnr\n");
    EXPECT_THROW(run_sweep(s.config, (s.folder / "out").string(), 1), InputError);
}

// A re-run may extend a sweep (more levels, views, models) but not change what
// its rows share: their rows would no longer answer the config.
TEST(Sweep, RefusesAFolderMadeWithOtherSettings) {
    SmallSweep s = small_sweep("sweep_settings");
    const std::string out = (s.folder / "out").string();
    run_sweep(s.config, out, 2);
    SweepConfig more_views = s.config;
    more_views.views.push_back("+X");
    EXPECT_EQ(run_sweep(more_views, out, 2).rows_skipped, 8u);
    const std::string results = test::read_text(s.folder / "out" / "results.csv");
    for (auto change : std::vector<std::function<void(SweepConfig&)>>{
             [](SweepConfig& c) { c.lod.flat_faces = 4; }, [](SweepConfig& c) { c.lod.resolution = 96; },
             [](SweepConfig& c) { c.width = 128; },
             [](SweepConfig& c) { c.sizing = SizingRule::per_level; }}) {
        SweepConfig changed = s.config;
        change(changed);
        try {
            run_sweep(changed, out, 2);
            ADD_FAILURE() << "a changed setting reused the folder's rows";
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find("settings.txt"), std::string::npos) << error.what();
        }
    }
    EXPECT_EQ(test::read_text(s.folder / "out" / "results.csv"), results);
}

// settings.txt names the build that made the rows (its executable's size and
// CRC-32): rows of another build are not taken, as it may draw other pixels.
TEST(Sweep, RefusesAFolderMadeByAnotherBuild) {
    SmallSweep s = small_sweep("sweep_build");
    const std::string out = (s.folder / "out").string();
    run_sweep(s.config, out, 2);
    const std::filesystem::path settings = s.folder / "out" / "settings.txt";
    const std::string text = test::read_text(settings);
    const std::size_t line = text.find("boxlod_build = ");
    ASSERT_NE(line, std::string::npos) << text;
    EXPECT_NE(text.find(" bytes, crc32 ", line), std::string::npos) << text;  // /proc/self/exe was read
    EXPECT_EQ(run_sweep(s.config, out, 2).rows_skipped, 8u);                  // the same build resumes
    test::write_text(settings, text.substr(0, line) + "boxlod_build = 1 bytes, crc32 00000000\n");
    try {
        run_sweep(s.config, out, 2);
        ADD_FAILURE() << "another build's rows were reused";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("settings.txt"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("boxlod_build = 1 bytes"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace boxlod
