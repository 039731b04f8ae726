#include "experiments/city/fly_through.h"

#include "data_gen/city.h"
#include "test_support.h"
#include "toolkit/selection/face_budget.h"
#include "toolkit/selection/strategy_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>

using namespace boxlod;

namespace {

CityPlan small_city(int buildings, int designs = 0) {
    CityOptions options;
    options.buildings = buildings;
    options.seed = 3;
    options.designs = designs;
    return plan_city(options);
}

FlyThroughOptions tiny_frames() {
    FlyThroughOptions options;
    set_manual(options.levels);  // every sub-tree boxed: each level has pages
    options.levels.min_texture_size = 64;
    options.width = 64;
    options.height = 48;
    options.error_every = 2;
    options.threads = 1;
    return options;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// One building and its levels, built once for the tests that only select and draw.
struct OneBuilding {
    CityPlan city = small_city(1);
    FlyThroughOptions options = tiny_frames();
    CityLevels levels = build_city_levels(city, options, true);
};
const OneBuilding& one_building() {
    static const OneBuilding built;
    return built;
}

// From 3 km straight towards the building's centre, ending 5 m outside its bounding sphere.
std::vector<CameraPose> dolly(const SelectionObject& object, int frames) {
    Eigen::Vector3f direction = Eigen::Vector3f(1, 0.3f, 0.6f).normalized();
    return line_path(object.center + direction * 3000, object.center + direction * (object.radius + 5),
                     frames);
}

}  // namespace

TEST(FlyThrough, LevelsAreBakedForDoublingDistances) {
    const OneBuilding& b = one_building();
    ASSERT_EQ(b.levels.buildings.size(), 1u);
    const SelectionObject& object = b.levels.objects[0];
    int n = coarsest_level(object);
    ASSERT_GE(n, 3);
    EXPECT_EQ(b.levels.max_level, n);
    EXPECT_EQ(b.levels.designs[0].levels.size(), std::size_t(n) + 1);  // 0..n, packed
    EXPECT_FALSE(object.levels[0].sizing);
    for (int c = 1; c <= n; ++c) {
        const SelectionLevel& level = object.levels[std::size_t(c)];
        ASSERT_TRUE(level.sizing);
        EXPECT_EQ(level.sizing->distance, 20 * std::ldexp(1.0f, c - 1));
        EXPECT_EQ(level.sizing->resolution, 48);
        ASSERT_TRUE(level.error);  // measured: asked for
        EXPECT_GE(level.error->error, 0);
        EXPECT_EQ(level.error->distance, level.sizing->distance);
        EXPECT_GT(level.faces, 0u);
    }
    EXPECT_EQ(object.levels[std::size_t(n)].faces, 6u);  // the root's box
    EXPECT_GT(object.levels[0].faces, object.levels[std::size_t(n - 1)].faces);
    EXPECT_GT(b.levels.street_faces, 0u);
}

TEST(FlyThrough, ACloserCameraNeverPicksACoarserLevel) {
    const OneBuilding& b = one_building();
    std::vector<CameraPose> path = dolly(b.levels.objects[0], 40);
    for (const char* text : {"texel", "distance:40,80,160,320,640", "pixels:20000,5000,1000,200",
                             "ratio:0.2,0.05,0.01", "diagonal:4,200,square-root"}) {
        for (double hysteresis : {0.0, 0.3}) {
            FlyThroughOptions options = b.options;
            options.strategy = parse_strategy(text, "test");
            options.hysteresis = hysteresis;
            options.error_every = 0;
            std::vector<FrameRecord> frames = fly_through(b.levels, path, options);
            ASSERT_EQ(frames.size(), path.size());
            for (std::size_t k = 1; k < frames.size(); ++k)
                EXPECT_LE(frames[k].levels[0], frames[k - 1].levels[0]) << text << " frame " << k;
            EXPECT_GT(frames.front().levels[0], frames.back().levels[0])
                << text << ": the dolly changes nothing";
        }
    }
}

// Measured switching (--strategy measured): each level a distance draws gets
// the distance from which its design's chain measured it within the error,
// farther for coarser levels, and a dolly from 3 km passes from coarse to fine.
TEST(FlyThrough, MeasuredSwitchingTakesTheChainsSwitchDistances) {
    FlyThroughOptions options = tiny_frames();
    options.strategy = parse_strategy("measured:0.1", "test");
    options.error_every = 0;
    const CityLevels levels = build_city_levels(small_city(1), options, false);
    const SelectionObject& object = levels.objects[0];
    std::vector<double> switched_at;
    for (int c = 1; c <= coarsest_level(object); ++c)
        if (object.levels[std::size_t(c)].switch_distance)
            switched_at.push_back(*object.levels[std::size_t(c)].switch_distance);
    ASSERT_GE(switched_at.size(), 1u);
    for (std::size_t k = 1; k < switched_at.size(); ++k) EXPECT_GT(switched_at[k], switched_at[k - 1]);
    const std::vector<FrameRecord> frames = fly_through(levels, dolly(object, 40), options);
    for (std::size_t k = 1; k < frames.size(); ++k)
        EXPECT_LE(frames[k].levels[0], frames[k - 1].levels[0]) << "frame " << k;
    EXPECT_GT(frames.front().levels[0], 0);
    EXPECT_EQ(frames.back().levels[0], 0);
}

// Levels are unpacked on demand: how much stays unpacked changes how often a level is
// unpacked again, never what a frame shows; each level is unpacked once when all fit.
// (The full-detail frames compared are unpacked apart, not through this cache.)
TEST(FlyThrough, FramesDoNotDependOnTheMemoryBudget) {
    const OneBuilding& b = one_building();
    std::vector<CameraPose> path = dolly(b.levels.objects[0], 12);
    path.insert(path.end(), path.rbegin(), path.rend());  // in and out again: the levels come back
    FlyThroughOptions options = b.options;
    options.strategy = parse_strategy("distance:40,80,160,320,640", "test");
    std::vector<std::vector<std::uint8_t>> images[2];
    std::vector<FrameRecord> frames[2];
    for (int run = 0; run < 2; ++run) {
        options.memory_budget = run == 0 ? 0 : std::size_t(1) << 30;
        frames[run] = fly_through(b.levels, path, options, [&](int, const Image8& image, const FrameRecord&) {
            images[run].push_back(image.pixels);
        });
    }
    EXPECT_EQ(images[0], images[1]);
    std::set<int> levels_drawn;
    std::size_t unpacked[2] = {0, 0};
    for (int run = 0; run < 2; ++run)
        for (const FrameRecord& frame : frames[run]) {
            unpacked[run] += frame.levels_unpacked;
            levels_drawn.insert(frame.levels[0]);
        }
    ASSERT_GE(levels_drawn.size(), 4u);
    EXPECT_EQ(unpacked[1], levels_drawn.size());
    EXPECT_GT(unpacked[0], unpacked[1]);  // with no budget, a level coming back is unpacked again
}

// The frame at full detail is unpacked and drawn in groups, each over the
// earlier ones' depth: the same picture, so the same errors, for any group size.
TEST(FlyThrough, FullDetailDrawnInGroupsIsOneRenderOfAll) {
    const CityPlan city = small_city(6);
    FlyThroughOptions options = tiny_frames();
    options.error_every = 1;
    const CityLevels levels = build_city_levels(city, options, false);
    const std::vector<CameraPose> path = city_path("orbit", city, levels.bounds, options.fovy, 3);
    std::vector<std::vector<double>> errors[2];
    for (int run = 0; run < 2; ++run) {
        options.full_detail_group_bytes =
            run == 0 ? std::size_t(1) << 40 : 1;  // one group; a building a group
        for (const FrameRecord& frame : fly_through(levels, path, options)) {
            ASSERT_TRUE(frame.error);
            errors[run].push_back({frame.error->psnr, frame.error->ssim, frame.error->flip});
        }
    }
    EXPECT_EQ(errors[0], errors[1]);
    EXPECT_GT(errors[0][0][2], 0);  // the levels differ from full detail: the errors say something
}

// cost is what that mode loads of the streets and each building's level.
TEST(FlyThrough, FrameCostIsWhatNormalMappingLoads) {
    const OneBuilding& b = one_building();
    FlyThroughOptions options = b.options;
    options.strategy = parse_strategy("distance:40,80,160,320,640", "test");
    std::size_t boxed_frames = 0;
    for (const FrameRecord& frame : fly_through(b.levels, dolly(b.levels.objects[0], 12), options)) {
        std::vector<const CostParts*> drawn = {&b.levels.street_cost,
                                               &b.levels.designs[0].costs[std::size_t(frame.levels[0])]};
        const ModelCost expected = drawn_cost(drawn, RenderMode::normal), every_map = combined_cost(drawn);
        EXPECT_EQ(frame.cost.texture_bytes_gpu, expected.texture_bytes_gpu);
        EXPECT_EQ(frame.cost.bytes(), expected.bytes());
        if (frame.levels[0] > 0) {
            EXPECT_LT(frame.cost.texture_bytes, every_map.texture_bytes);  // the level's height pages
            ++boxed_frames;
        }
    }
    EXPECT_GT(boxed_frames, 0u);
}

TEST(FlyThrough, FacesStayWithinAnAchievableBudget) {
    CityPlan city = small_city(4);
    FlyThroughOptions options = tiny_frames();
    options.strategy = DistanceBands{{1e6}};  // the strategy alone keeps every building at level 0
    CityLevels levels = build_city_levels(city, options, false);
    std::vector<CameraPose> path = city_path("orbit", city, levels.bounds, options.fovy, 3);
    std::vector<int> coarsest;
    for (const SelectionObject& object : levels.objects) coarsest.push_back(coarsest_level(object));
    std::size_t least = faces_drawn(levels.objects, coarsest, levels.street_faces);
    std::size_t most =
        faces_drawn(levels.objects, std::vector<int>(levels.objects.size(), 0), levels.street_faces);
    for (std::size_t budget : {least, (least + most) / 2, most - 1}) {
        options.face_budget = budget;
        for (const FrameRecord& frame : fly_through(levels, path, options)) {
            EXPECT_LE(frame.faces, budget);
            EXPECT_EQ(frame.faces, faces_drawn(levels.objects, frame.levels, levels.street_faces));
        }
    }
    options.face_budget.reset();
    EXPECT_EQ(fly_through(levels, path, options).front().faces, most);
}

TEST(FlyThrough, OutputsAreIdenticalForOneAndTwoThreads) {
    CityPlan city = small_city(3);
    FlyThroughOptions options = tiny_frames();
    options.strategy = parse_strategy("distance:100,200,400", "test");
    auto one = test::scratch_folder("fly_through_1"), two = test::scratch_folder("fly_through_2");
    options.threads = 1;
    CityLevels levels = build_city_levels(city, options, false);
    std::vector<CameraPose> path = city_path("orbit", city, levels.bounds, options.fovy, 5);
    FlyThroughReport report = run_fly_through(levels, path, options, {1}, one.string()).at(0);
    options.threads = 2;
    run_fly_through(build_city_levels(city, options, false), path, options, {1}, two.string());

    std::string csv = test::read_text(one / "frames.csv");
    EXPECT_EQ(csv, test::read_text(two / "frames.csv"));
    std::vector<std::string> rows = lines_of(csv);
    ASSERT_EQ(rows.size(), 6u);
    std::string header =
        "frame,strategy,detail,faces,triangles,draw_calls,mesh_bytes,texture_bytes,texture_bytes_gpu,bytes,"
        "buildings";
    for (std::size_t c = 0; c < report.level_totals.size(); ++c) header += ",level_" + std::to_string(c);
    EXPECT_EQ(rows[0], header + ",levels_changed,psnr,ssim,flip");
    EXPECT_EQ(rows[1].rfind("0,\"distance:100,200,400\",1,", 0), 0u);
    EXPECT_EQ(rows[2].substr(rows[2].size() - 3), ",,,");  // frame 1 is not sampled
    EXPECT_NE(rows[3].substr(rows[3].size() - 3), ",,,");  // frame 2 is
    EXPECT_EQ(report.sampled_frames, 3u);
    EXPECT_EQ(report.frames, 5u);
    EXPECT_EQ(report.buildings, 3u);
    EXPECT_EQ(lines_of(test::read_text(one / "timings.csv")).front(),
              "frame,detail,select_seconds,unpack_seconds,render_seconds,levels_unpacked,resident_bytes");
    for (int k = 0; k < 5; ++k) {
        std::string name = "frames/frame_000" + std::to_string(k) + ".png";
        ASSERT_TRUE(std::filesystem::exists(one / name)) << name;
        EXPECT_EQ(test::read_text(one / name), test::read_text(two / name)) << name;
    }
    EXPECT_EQ(test::read_text(one / "contact_sheet.png"), test::read_text(two / "contact_sheet.png"));
    Image8 sheet = read_image((one / "contact_sheet.png").string());
    EXPECT_EQ(sheet.width, 4 * 64 + 5 * 2);
    EXPECT_EQ(sheet.height, 2 * 48 + 3 * 2);
}

// The detail bias: as if every building were 1/K as far, so a larger K never picks a
// coarser level for any building on any frame, for every strategy (faces need not follow:
// a fine level can draw more faces than a coarser one); several details share one build
// and each gets its own images.
TEST(FlyThrough, MoreDetailNeverPicksACoarserLevel) {
    CityPlan city = small_city(3);
    FlyThroughOptions options = tiny_frames();
    options.hysteresis = 0;
    const std::vector<CameraPose> path =
        city_path("orbit", city, build_city_levels(city, options, false).bounds, options.fovy, 4);
    for (const char* text :
         {"distance:100,200,400", "pixels:4000,1000,250", "ratio:0.5,0.1,0.02", "diagonal:4,64", "texel"}) {
        options.strategy = parse_strategy(text, "test");
        CityLevels levels = build_city_levels(city, options, false);
        std::vector<FrameRecord> previous;
        int level_sum[2] = {0, 0};
        for (double detail : {0.25, 1.0, 4.0}) {
            options.detail = detail;
            std::vector<FrameRecord> frames = fly_through(levels, path, options);
            for (std::size_t k = 0; k < frames.size(); ++k)
                for (std::size_t b = 0; b < frames[k].levels.size(); ++b) {
                    if (!previous.empty()) {
                        EXPECT_LE(frames[k].levels[b], previous[k].levels[b]) << text << " detail " << detail;
                    }
                    if (detail != 1.0) level_sum[detail > 1] += frames[k].levels[b];
                }
            previous = frames;
        }
        EXPECT_LT(level_sum[1], level_sum[0]) << text << ": the bias changes nothing on this path";
    }
    options.detail = 1;
    options.strategy = parse_strategy("texel", "test");
    auto folder = test::scratch_folder("fly_through_details");
    std::vector<FlyThroughReport> reports =
        run_fly_through(build_city_levels(city, options, false), path, options, {0.5, 2}, folder.string());
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_EQ(reports[1].detail, 2);
    for (const char* run : {"detail_0.5", "detail_2"}) {
        EXPECT_TRUE(std::filesystem::exists(folder / run / "contact_sheet.png")) << run;
        EXPECT_TRUE(std::filesystem::exists(folder / run / "frames" / "frame_0003.png")) << run;
    }
    std::vector<std::string> rows = lines_of(test::read_text(folder / "frames.csv"));
    ASSERT_EQ(rows.size(), 1u + 2 * 4);
    EXPECT_EQ(rows[1].rfind("0,texel,0.5,", 0), 0u);
    EXPECT_EQ(rows[5].rfind("0,texel,2,", 0), 0u);
}

// A frame's cost: meshes and draw calls of the streets and each building at its
// level add up; the grammar textures every building copies are paid for once, so
// all buildings at level 0 cost what the city's own textures do.
TEST(FlyThrough, FrameCostPaysEachSharedTextureOnce) {
    CityPlan city = small_city(3);
    CityLevels levels = build_city_levels(city, tiny_frames(), false);
    std::vector<const CostParts*> originals = {&levels.street_cost}, coarsest = {&levels.street_cost};
    for (const CityBuilding& building : levels.buildings) {
        const DesignLevels& design = levels.designs[building.design];
        originals.push_back(&design.costs.front());
        coarsest.push_back(&design.costs.back());
        EXPECT_EQ(design.costs.size(), design.triangles.size());
    }
    ModelCost all = combined_cost(originals), whole = model_cost(generate_city(city.options));
    EXPECT_EQ(all.texture_bytes, whole.texture_bytes);
    EXPECT_EQ(all.texture_bytes_gpu, whole.texture_bytes_gpu);
    EXPECT_EQ(all.mesh_bytes, whole.mesh_bytes);
    EXPECT_GE(all.draw_calls, whole.draw_calls);
    EXPECT_LT(combined_cost(coarsest).mesh_bytes, all.mesh_bytes);
}

// Lots showing one design share its LoD, built once; without sharing each
// builds its own, and every statistic and frame comes out the same.
TEST(FlyThrough, RepeatedDesignsAreBuiltOnceAndDrawnAsIfEachHadItsOwn) {
    CityPlan city = small_city(6, 2);
    FlyThroughOptions options = tiny_frames();
    options.strategy = parse_strategy("distance:60,120,240", "test");
    CityLevels shared = build_city_levels(city, options, false);
    std::vector<CameraPose> path = city_path("street", city, shared.bounds, options.fovy, 4);
    std::set<std::size_t> designs_shown;
    for (const CityLot& lot : city.lots) designs_shown.insert(lot.design);
    EXPECT_EQ(shared.designs.size(), designs_shown.size());
    EXPECT_EQ(shared.buildings.size(), 6u);
    options.share_designs = false;
    CityLevels own = build_city_levels(city, options, false);
    EXPECT_EQ(own.designs.size(), 6u);
    EXPECT_EQ(own.bounds.min, shared.bounds.min);
    EXPECT_EQ(own.bounds.max, shared.bounds.max);
    auto a = test::scratch_folder("fly_through_shared"), b = test::scratch_folder("fly_through_own");
    FlyThroughReport report = run_fly_through(shared, path, options, {1}, a.string()).at(0);
    run_fly_through(own, path, options, {1}, b.string());
    EXPECT_EQ(test::read_text(a / "frames.csv"), test::read_text(b / "frames.csv"));
    for (int k = 0; k < 4; ++k) {
        std::string name = "frames/frame_000" + std::to_string(k) + ".png";
        EXPECT_EQ(test::read_text(a / name), test::read_text(b / name)) << name;
    }
    EXPECT_GT(report.level_totals.front() + report.level_totals.back(), 0u);
    EXPECT_LT(report.level_totals.front(), 4u * 6u);  // some buildings are drawn as boxes
}

// With keep_small_subtrees no level of a building draws more faces than its original
// (the manual's cut boxes single quads: its level 1 can draw more).
TEST(FlyThrough, KeptSmallSubtreesNeverCostMoreFacesThanTheOriginal) {
    CityPlan city = small_city(2);
    FlyThroughOptions options = tiny_frames();
    options.levels.keep_small_subtrees = true;
    CityLevels levels = build_city_levels(city, options, false);
    for (const SelectionObject& object : levels.objects)
        for (std::size_t c = 1; c < object.levels.size(); ++c)
            EXPECT_LE(object.levels[c].faces, object.levels[0].faces) << c;
    options.levels.keep_small_subtrees = false;
    CityLevels manual = build_city_levels(city, options, false);
    EXPECT_GT(manual.objects[0].levels[1].faces, levels.objects[0].levels[1].faces);
}

// A city's folder is replaced whole only when it holds nothing but what a
// fly-through writes; a user's own file there keeps it from being swapped.
TEST(FlyThrough, KnowsTheFilesItWritesIntoItsFolder) {
    for (const char* name :
         {"frames.csv", "timings.csv", "frames", "frames/frame_0007.png", "contact_sheet.png", "detail_0.5",
          "detail_2/frames/frame_0000.png", "detail_1e-05/contact_sheet.png"})
        EXPECT_TRUE(is_fly_through_file(name)) << name;
    for (const char* name :
         {"", "notes.txt", "frames/notes.txt", "detail_2/notes.txt", "tileset.json", "results.csv"})
        EXPECT_FALSE(is_fly_through_file(name)) << name;
}
