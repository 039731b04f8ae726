#include "toolkit/selection/lod_selection.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace boxlod;

namespace {

SelectionView perspective(const Eigen::Vector3f& position, const Eigen::Vector3f& target, float fovy,
                          int width, int height) {
    SelectionView view;
    view.camera.position = position;
    view.camera.target = target;
    view.camera.fovy_degrees = fovy;
    view.width = width;
    view.height = height;
    return view;
}

// A camera on the +Z axis at `distance` from the origin, looking at it.
SelectionView on_axis(float distance, float fovy, int width, int height) {
    return perspective({0, 0, distance}, {0, 0, 0}, fovy, width, height);
}

SelectionObject sphere(float radius, int levels) {
    SelectionObject object;
    object.radius = radius;
    object.levels.resize(levels);
    return object;
}

TextureSizing sizing(float distance, float fovy = 45, float resolution = 1080) {
    TextureSizing s;
    s.distance = distance;
    s.fovy_degrees = fovy;
    s.resolution = resolution;
    return s;
}

// Window pixel coordinates of a world point (pixel centres aside): x right, y up.
Eigen::Vector2d to_pixels(const SelectionView& view, const Eigen::Vector3f& point) {
    float aspect = float(view.width) / float(view.height);
    Eigen::Vector4f clip =
        projection_matrix(view.camera, aspect) * view_matrix(view.camera) * point.homogeneous();
    return {(clip.x() / clip.w() + 1) * view.width / 2.0, (clip.y() / clip.w() + 1) * view.height / 2.0};
}

// A building-sized object with levels 1..4 baked for 25, 50, 100, 200 m and errors
// measured at 100 m, and one instance of every strategy tuned so that a fly-away from
// 5 m to 3 km passes all its levels.
SelectionObject building() {
    OrientedBox box;
    box.center = {3, 1, -2};
    box.half_extents = {4, 6, 12};  // radius 14, diagonal 28
    std::vector<SelectionLevel> levels(5);
    const double distances[] = {25, 50, 100, 200}, errors[] = {0.002, 0.005, 0.01, 0.02};
    for (int c = 1; c <= 4; ++c) {
        levels[c].faces = std::size_t(1000 >> (2 * c));
        levels[c].sizing = sizing(float(distances[c - 1]));
        levels[c].error = MeasuredError{errors[c - 1], 100, 45, 1080};
    }
    return selection_object(box, std::move(levels));
}

std::vector<std::pair<std::string, Strategy>> every_strategy() {
    return {
        {"distance bands", DistanceBands{{30, 60, 120, 240}}},
        {"pixel count", PixelCount{{2e5, 5e4, 1.2e4, 3e3}}},
        {"screen ratio", ScreenRatio{{0.2, 0.05, 0.0125, 0.003}}},
        {"box diagonal linear", BoxDiagonal{50, 600, DiagonalInterpolation::linear}},
        {"box diagonal square", BoxDiagonal{50, 600, DiagonalInterpolation::square}},
        {"box diagonal square root", BoxDiagonal{50, 600, DiagonalInterpolation::square_root}},
        {"texel exact", TexelExact{}},
        {"texel exact under a budget", TexelExact{0.01}},
    };
}

// The building seen from `distance` along a fixed oblique direction, 1280 x 720, fovy 45.
SelectionView fly_away(const SelectionObject& object, double distance) {
    Eigen::Vector3f direction = Eigen::Vector3f(1, 0.5f, 0.25f).normalized();
    return perspective(object.center + direction * float(distance), object.center, 45, 1280, 720);
}

}  // namespace

TEST(LodSelection, PixelCountOfASphereOnTheAxisIsTheProjectedDisc) {
    // fovy 90 on 1000 pixels: f = 500. r = 3 at d = 5: silhouette radius f r / sqrt(d^2 - r^2) = 375.
    SelectionObject object = sphere(3, 4);
    SelectionView view = on_axis(5, 90, 1600, 1000);
    EXPECT_NEAR(sphere_pixel_count(object, view), M_PI * 375 * 375, 1e-6 * M_PI * 375 * 375);
    // The tangent point where the silhouette cone touches the sphere lands 375 pixels
    // from the centre through the renderer's own matrices (along x on a wide viewport).
    Eigen::Vector3f tangent(2.4f, 0, 1.8f);  // |tangent| = 3, and it is 4 from the camera
    EXPECT_NEAR((to_pixels(view, tangent) - to_pixels(view, {0, 0, 0})).norm(), 375, 1e-3);

    PixelCount strategy{{2e5, 1e5, 1e4}};
    Choice near = choose_level(strategy, object, view);
    EXPECT_EQ(near.level, 0);
    // At d = 10: pi (3 * 500)^2 / 91 = 77677.4 pixels: below 2e5 and 1e5, not below 1e4.
    Choice far = choose_level(strategy, object, on_axis(10, 90, 1600, 1000));
    EXPECT_NEAR(far.value, M_PI * 2250000 / 91, 1e-3);
    EXPECT_EQ(far.level, 2);
    EXPECT_EQ(choose_level(strategy, object, on_axis(1000, 90, 1600, 1000)).level, 3);
}

TEST(LodSelection, OrthographicPixelCountIsTheDiscInWindowPixels) {
    SelectionObject object = sphere(2, 3);
    SelectionView view = on_axis(50, 45, 1600, 1000);
    view.camera.orthographic = true;
    view.camera.left = -8;  // 100 px per unit
    view.camera.right = 8;
    view.camera.bottom = -5;
    view.camera.top = 5;
    EXPECT_NEAR(sphere_pixel_count(object, view), M_PI * 200 * 200, 1e-6);
    EXPECT_NEAR(strategy_value(ScreenRatio{}, object, view), M_PI * 40000 / 1.6e6, 1e-12);
    // The distance does not matter to an orthographic camera.
    view.camera.position = {0, 0, 500};
    EXPECT_NEAR(sphere_pixel_count(object, view), M_PI * 200 * 200, 1e-6);
    EXPECT_EQ(choose_level(PixelCount{{2e5, 1e5}}, object, view).level, 1);  // 125664 pixels
    // A window stretched over a square viewport: 62.5 px per unit across, 100 up.
    view.width = 1000;
    EXPECT_NEAR(sphere_pixel_count(object, view), M_PI * 4 * 62.5 * 100, 1e-6);
}

TEST(LodSelection, ScreenRatioIsTheSameAtTwiceTheResolution) {
    SelectionObject object = sphere(5, 4);
    SelectionView small = on_axis(60, 50, 800, 600), large = on_axis(60, 50, 1600, 1200);
    double ratio = strategy_value(ScreenRatio{}, object, small);
    EXPECT_GT(ratio, 0.01);
    EXPECT_NEAR(strategy_value(ScreenRatio{}, object, large), ratio, 1e-12);
    EXPECT_NEAR(sphere_pixel_count(object, large), 4 * sphere_pixel_count(object, small), 1e-6);
    // The same thresholds pick the same level on both screens; pixel counts do not.
    ScreenRatio by_ratio{{ratio * 1.5, ratio / 1.5}};
    EXPECT_EQ(choose_level(by_ratio, object, small).level, 1);
    EXPECT_EQ(choose_level(by_ratio, object, large).level, 1);
    double pixels = sphere_pixel_count(object, small);
    PixelCount by_pixels{{pixels * 1.5, pixels / 1.5}};
    EXPECT_EQ(choose_level(by_pixels, object, small).level, 1);
    EXPECT_EQ(choose_level(by_pixels, object, large).level, 0);
}

TEST(LodSelection, BoxDiagonalOfABoxSeenHeadOnAndItsInterpolations) {
    OrientedBox box;
    box.center = {1, 2, 0};
    box.half_extents = {3, 4, 0};  // a flat 6 x 8 box facing +Z: diagonal 10
    SelectionObject object = selection_object(box, std::vector<SelectionLevel>(5));
    EXPECT_FLOAT_EQ(object.radius, 5);
    SelectionView view = perspective({1, 2, 20}, {1, 2, 0}, 60, 800, 600);
    double x = box_diagonal_pixels(object, view);
    // The projected corners, through the renderer's matrices: 10 * (300 / tan 30) / 20 = 259.8.
    EXPECT_NEAR(x, (to_pixels(view, {4, 6, 0}) - to_pixels(view, {-2, -2, 0})).norm(), 1e-3);
    EXPECT_NEAR(x, 150 * std::sqrt(3.0), 1e-9);

    BoxDiagonal linear{100, 400, DiagonalInterpolation::linear};
    BoxDiagonal square{100, 400, DiagonalInterpolation::square};
    BoxDiagonal root{100, 400, DiagonalInterpolation::square_root};
    EXPECT_NEAR(diagonal_weight(linear, x), (x - 100) / 300, 1e-12);
    EXPECT_NEAR(diagonal_weight(square, x), (x * x - 1e4) / 15e4, 1e-12);
    EXPECT_NEAR(diagonal_weight(root, x), (std::sqrt(x) - 10) / 10, 1e-12);
    // Square keeps less detail, square root more (interpolated-lod-selection.txt).
    EXPECT_LT(diagonal_weight(square, x), diagonal_weight(linear, x));
    EXPECT_GT(diagonal_weight(root, x), diagonal_weight(linear, x));
    // N = 4: detail floor(4 t) = 2 (t 0.533), 1 (t 0.383), 2 (t 0.612); level 4 - detail.
    EXPECT_EQ(choose_level(linear, object, view).level, 2);
    EXPECT_EQ(choose_level(square, object, view).level, 3);
    EXPECT_EQ(choose_level(root, object, view).level, 2);
    // Outside [min, max]: the coarsest level below, the original above.
    EXPECT_EQ(choose_level(BoxDiagonal{300, 400}, object, view).level, 4);
    EXPECT_EQ(choose_level(BoxDiagonal{100, 200}, object, view).level, 0);
    EXPECT_EQ(diagonal_weight(linear, 50), 0);
    EXPECT_EQ(diagonal_weight(linear, 500), 1);
}

TEST(LodSelection, DistanceBandsCountTheThresholdsPassed) {
    SelectionObject object = sphere(1, 4);
    DistanceBands bands{{10, 20, 40}};
    EXPECT_EQ(choose_level(bands, object, on_axis(5, 45, 640, 480)).level, 0);
    EXPECT_EQ(choose_level(bands, object, on_axis(10, 45, 640, 480)).level, 1);
    EXPECT_EQ(choose_level(bands, object, on_axis(25, 45, 640, 480)).level, 2);
    Choice far = choose_level(bands, object, on_axis(100, 45, 640, 480));
    EXPECT_EQ(far.value, 100);
    EXPECT_EQ(far.level, 3);
    // More thresholds than levels: the coarsest level there is.
    EXPECT_EQ(choose_level(bands, sphere(1, 3), on_axis(100, 45, 640, 480)).level, 2);
    EXPECT_EQ(choose_level(bands, sphere(1, 0), on_axis(100, 45, 640, 480)).level, 0);
}

// Measured switching: the coarsest level whose measured switch distance the
// camera has passed; a level no distance draws (level 2 here) is never picked;
// the detail bias judges the distance / K.
TEST(LodSelection, MeasuredSwitchingPicksTheCoarsestLevelSwitchedIn) {
    SelectionObject object = sphere(1, 4);
    object.levels[1].switch_distance = 10;
    object.levels[3].switch_distance = 40;
    const MeasuredSwitch measured;
    EXPECT_EQ(choose_level(measured, object, on_axis(5, 45, 640, 480)).level, 0);
    EXPECT_EQ(choose_level(measured, object, on_axis(15, 45, 640, 480)).level, 1);
    EXPECT_EQ(choose_level(measured, object, on_axis(30, 45, 640, 480)).level, 1);
    EXPECT_EQ(choose_level(measured, object, on_axis(50, 45, 640, 480)).level, 3);
    EXPECT_EQ(choose_level(scale_detail(measured, 2), object, on_axis(50, 45, 640, 480)).level, 1);
    EXPECT_EQ(choose_level(measured, sphere(1, 4), on_axis(1000, 45, 640, 480)).level,
              0);  // nothing measured: the original
}

TEST(LodSelection, TexelExactAcceptsALevelFromItsBakedDistanceOn) {
    SelectionObject object = sphere(2, 4);
    for (int c = 1; c <= 3; ++c) object.levels[c].sizing = sizing(25.0f * float(1 << c));  // 50, 100, 200
    Eigen::Vector3f direction = Eigen::Vector3f(1, 1, 1).normalized();
    auto at = [&](float d, int height = 1080) {
        return perspective(direction * d, {0, 0, 0}, 45, 1920, height);
    };

    Choice baked = choose_level(TexelExact{}, object, at(100));
    EXPECT_NEAR(baked.value, 2 * 100 * std::tan(M_PI / 8) / 1080, 1e-6);
    EXPECT_EQ(baked.level, 2);  // baked for 100: acceptable; level 3 (200) not yet
    EXPECT_EQ(choose_level(TexelExact{}, object, at(50)).level, 1);  // half the distance: level 2 is not
    EXPECT_EQ(choose_level(TexelExact{}, object, at(49)).level, 0);
    EXPECT_EQ(choose_level(TexelExact{}, object, at(99)).level, 1);
    EXPECT_EQ(choose_level(TexelExact{}, object, at(400)).level, 3);
    // Twice the resolution halves the pixel: the level baked for 100 no longer holds at 100.
    EXPECT_EQ(choose_level(TexelExact{}, object, at(100, 2160)).level, 1);
    // A level without a sizing is never texel-exact.
    object.levels[3].sizing.reset();
    EXPECT_EQ(choose_level(TexelExact{}, object, at(400)).level, 2);
}

TEST(LodSelection, TexelExactUnderAnErrorBudgetScalesTheErrorWithDistance) {
    SelectionObject object = sphere(2, 4);
    const double errors[] = {0.01, 0.03, 0.08};
    for (int c = 1; c <= 3; ++c) {
        object.levels[c].sizing = sizing(10);  // texel-exact everywhere below
        object.levels[c].error = MeasuredError{errors[c - 1], 100, 45, 1080};
    }
    auto at = [](float d) { return on_axis(d, 45, 1920, 1080); };
    // e d_ref / d: 0.08 measured at 100 is 0.02 at 400.
    EXPECT_NEAR(scaled_error(*object.levels[3].error, pixel_footprint(object, at(400))), 0.02, 1e-7);
    TexelExact budget{0.02};
    EXPECT_EQ(choose_level(budget, object, at(500)).level, 3);  // 0.016
    EXPECT_EQ(choose_level(budget, object, at(300)).level, 2);  // 0.027 too much; 0.01
    EXPECT_EQ(choose_level(budget, object, at(120)).level, 1);  // 0.025 too much; 0.0083
    EXPECT_EQ(choose_level(budget, object, at(40)).level, 0);   // 0.025 too much
    EXPECT_EQ(choose_level(TexelExact{}, object, at(40)).level, 3);
    // No measured error: not acceptable under a budget.
    object.levels[1].error.reset();
    EXPECT_EQ(choose_level(budget, object, at(120)).level, 0);
}

TEST(LodSelection, NoStrategyPicksAFinerLevelAsTheCameraMovesAway) {
    SelectionObject object = building();
    for (const auto& [name, strategy] : every_strategy()) {
        SCOPED_TRACE(name);
        int previous = 0, previous_selected = 0;
        int lowest = 99, highest = -1;
        Selector selector;
        for (double d = 5; d < 3000; d *= 1.03) {
            SelectionView view = fly_away(object, d);
            Choice choice = choose_level(strategy, object, view);
            ASSERT_FALSE(std::isnan(choice.value)) << d;
            ASSERT_GE(choice.level, previous) << d;
            int selected = select_level(selector, strategy, object, view);
            ASSERT_GE(selected, previous_selected) << d;
            previous = choice.level;
            previous_selected = selected;
            lowest = std::min(lowest, choice.level);
            highest = std::max(highest, choice.level);
        }
        EXPECT_EQ(lowest, 0);
        EXPECT_EQ(highest, 4);
        EXPECT_EQ(previous_selected, 4);
    }
}

TEST(LodSelection, HysteresisHoldsTheLevelWithinTheMarginAndSwitchesBeyondIt) {
    SelectionObject object = building();
    const double margin = 0.04, wobble = 0.01, cross = 0.05;  // relative, in distance
    for (const auto& [name, strategy] : every_strategy()) {
        // Every level change of the fly-away, located to 1e-7 by bisection.
        int changes = 0;
        double d = 1.2 * object.radius;
        int level = choose_level(strategy, object, fly_away(object, d)).level;
        while (d < 3000) {
            double next = d * 1.03;
            int next_level = choose_level(strategy, object, fly_away(object, next)).level;
            if (next_level == level) {
                d = next;
                continue;
            }
            double lo = d, hi = next;  // level at lo, another at hi
            while (hi / lo > 1 + 1e-7) {
                double mid = (lo + hi) / 2;
                (choose_level(strategy, object, fly_away(object, mid)).level == level ? lo : hi) = mid;
            }
            next_level = choose_level(strategy, object, fly_away(object, hi)).level;
            double threshold = (lo + hi) / 2;
            SCOPED_TRACE(name + " at " + std::to_string(threshold));
            auto level_at = [&](double factor) {
                return choose_level(strategy, object, fly_away(object, threshold * factor)).level;
            };
            // The set-up: no other threshold within `cross`, and the wobble does cross this one.
            ASSERT_EQ(level_at(1 - cross), level);
            ASSERT_EQ(level_at(1 + cross), next_level);
            ASSERT_EQ(level_at(1 - wobble), level);
            ASSERT_EQ(level_at(1 + wobble), next_level);

            Selector selector{margin};
            auto select_at = [&](double factor) {
                return select_level(selector, strategy, object, fly_away(object, threshold * factor));
            };
            EXPECT_EQ(select_at(1 - cross), level);
            for (int frame = 0; frame < 10; ++frame)
                EXPECT_EQ(select_at(frame % 2 ? 1 - wobble : 1 + wobble), level);
            EXPECT_EQ(select_at(1 + cross), next_level);
            for (int frame = 0; frame < 10; ++frame)
                EXPECT_EQ(select_at(frame % 2 ? 1 + wobble : 1 - wobble), next_level);
            EXPECT_EQ(select_at(1 - cross), level);
            // Without a margin the selector follows every wobble.
            Selector eager{0};
            EXPECT_EQ(select_level(eager, strategy, object, fly_away(object, threshold * (1 - wobble))),
                      level);
            EXPECT_EQ(select_level(eager, strategy, object, fly_away(object, threshold * (1 + wobble))),
                      next_level);

            ++changes;
            level = next_level;
            d = hi;
        }
        EXPECT_GE(changes, 3) << name;
    }
}

TEST(LodSelection, DegenerateInputsGiveTheFinestOrCoarsestLevelWithoutNaN) {
    SelectionObject object = building();
    for (const auto& [name, strategy] : every_strategy()) {
        SCOPED_TRACE(name);
        // The camera inside the bounding sphere, and exactly at its center: the original,
        // even where a strategy alone would not say so (a 280 m block, beyond every band).
        OrientedBox block = *object.box;
        block.half_extents *= 20;
        SelectionObject large = selection_object(block, object.levels);
        for (float d : {0.0f, 7.0f, 279.0f}) {
            SelectionView view = fly_away(large, d);
            if (d == 0) view.camera.target = large.center + Eigen::Vector3f(0, 0, -1);
            Choice choice = choose_level(strategy, large, view);
            EXPECT_FALSE(std::isnan(choice.value)) << d;
            EXPECT_EQ(choice.level, 0) << d;
        }
        // The selector follows at once, whatever its margin.
        Selector selector{0.5};
        EXPECT_EQ(select_level(selector, strategy, object, fly_away(object, 3000)), 4);
        EXPECT_EQ(select_level(selector, strategy, object, fly_away(object, 5)), 0);

        // Zero radius (and a zero box): nothing to see, the coarsest level, from anywhere.
        SelectionObject point = object;
        point.radius = 0;
        point.box->half_extents.setZero();
        for (float d : {0.0f, 1.0f, 50.0f}) {
            SelectionView view = fly_away(point, d);
            if (d == 0) view.camera.target = point.center + Eigen::Vector3f(0, 0, -1);
            Choice choice = choose_level(strategy, point, view);
            EXPECT_FALSE(std::isnan(choice.value)) << d;
            EXPECT_EQ(choice.level, 4) << d;
        }
    }
    // The values themselves at the degenerate points.
    SelectionView center = fly_away(object, 0);
    center.camera.target = object.center + Eigen::Vector3f(1, 0, 0);
    EXPECT_EQ(sphere_pixel_count(object, center), std::numeric_limits<double>::infinity());
    EXPECT_EQ(pixel_footprint(object, center), 0);
    SelectionObject point = sphere(0, 3);
    EXPECT_EQ(sphere_pixel_count(point, center), 0);
    EXPECT_EQ(box_diagonal_pixels(point, center), 0);
}

TEST(LodSelection, StrategiesWithDisorderedThresholdsAreRejected) {
    EXPECT_NO_THROW(validate_strategy(DistanceBands{{10, 20}}, "test"));
    EXPECT_THROW(validate_strategy(DistanceBands{{20, 10}}, "test"), InputError);
    EXPECT_NO_THROW(validate_strategy(PixelCount{{1e4, 1e3}}, "test"));
    EXPECT_THROW(validate_strategy(PixelCount{{1e3, 1e4}}, "test"), InputError);
    EXPECT_THROW(validate_strategy(ScreenRatio{{0.1, 0.1}}, "test"), InputError);
    EXPECT_THROW(validate_strategy(ScreenRatio{{-0.1}}, "test"), InputError);
    EXPECT_THROW(validate_strategy(BoxDiagonal{400, 100}, "test"), InputError);
    EXPECT_THROW(validate_strategy(TexelExact{std::nan("")}, "test"), InputError);
    EXPECT_NO_THROW(validate_strategy(TexelExact{0.05}, "test"));
    try {
        validate_strategy(DistanceBands{{20, 10}}, "params.txt");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("params.txt"), std::string::npos) << e.what();
    }
}

// The detail bias K: every strategy picks at distance d what it picked unbiased at d / K
// (the projected disc only far away, where it goes as 1/d^2; nearer, never the other way).
TEST(LodSelection, DetailPicksTheLevelOfACameraKTimesCloser) {
    SelectionObject object = building();  // radius 14
    for (const auto& [name, strategy] : every_strategy()) {
        SCOPED_TRACE(name);
        bool disc =
            std::holds_alternative<PixelCount>(strategy) || std::holds_alternative<ScreenRatio>(strategy);
        for (double detail : {0.5, 2.0, 3.0}) {
            Strategy biased = scale_detail(strategy, detail);
            for (double d = 50; d < 3000; d *= 1.37) {
                int unbiased = choose_level(strategy, object, fly_away(object, d / detail)).level;
                int level = choose_level(biased, object, fly_away(object, d)).level;
                if (!disc || d / detail > 400) {
                    EXPECT_EQ(level, unbiased) << d << " x" << detail;
                } else if (detail >
                           1) {  // the biased disc shrinks slower: never coarser than the unbiased one
                    EXPECT_LE(level, choose_level(strategy, object, fly_away(object, d)).level) << d;
                }
            }
        }
    }
    EXPECT_EQ(std::get<DistanceBands>(scale_detail(DistanceBands{{10, 20}}, 2)).distances,
              (std::vector<double>{20, 40}));
    EXPECT_EQ(std::get<PixelCount>(scale_detail(PixelCount{{400, 100}}, 2)).pixels,
              (std::vector<double>{100, 25}));
    EXPECT_EQ(std::get<TexelExact>(scale_detail(scale_detail(TexelExact{}, 2), 3)).detail, 6);
    EXPECT_THROW(scale_detail(TexelExact{}, 0), std::invalid_argument);
}
