#include "toolkit/lod/chain/error_by_distance.h"

#include "lod_scene.h"
#include "toolkit/model/framing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace boxlod;

namespace {

constexpr double never = std::numeric_limits<double>::infinity();

TextureSizing screen(float resolution) {
    TextureSizing s;
    s.fovy_degrees = 45;
    s.resolution = resolution;
    return s;
}

}  // namespace

// Half octaves from the framing distance to where the sphere spans 4 pixels.
TEST(ErrorByDistance, DistancesRunFromTheFramingDistanceToAFewPixels) {
    const Model model = test::lod_test_building();
    const std::vector<double> d = measured_distances(model, screen(1080));
    const Framing framing = model_framing(model);
    EXPECT_EQ(d.front(), double(framing_distance(framing, 45)));
    for (std::size_t k = 1; k < d.size(); ++k) EXPECT_NEAR(d[k] / d[k - 1], std::sqrt(2.0), 1e-9);
    auto pixels_at = [&](double distance) { return 1080 * framing.radius / (distance * std::tan(M_PI / 8)); };
    EXPECT_LE(pixels_at(d.back()), few_pixels);
    EXPECT_GT(pixels_at(d[d.size() - 2]), few_pixels);
    EXPECT_LT(measured_distances(model, screen(270)).size(),
              d.size());  // a smaller screen: fewer pixels to lose
}

// The original against itself is 0 at every distance; a level that differs
// is not, and the measure is the same on any number of threads.
TEST(ErrorByDistance, MeasuresWhatALevelChanges) {
    const Model model = test::lod_test_building();
    Model recoloured = model;
    recoloured.materials[2].base_color = {0.1f, 0.6f, 0.2f, 1};  // the roof
    const ErrorByDistance one =
        measure_error_by_distance(model, {&model, &recoloured}, screen(540), LodParameters{}, 1);
    ASSERT_EQ(one.errors.size(), 2u);
    for (std::size_t d = 0; d < one.distances.size(); ++d) {
        EXPECT_EQ(one.errors[0][d], 0) << d;
        EXPECT_GT(one.errors[1][d], 0.05) << d;  // a green roof instead of a red one, on every view
    }
    const ErrorByDistance two =
        measure_error_by_distance(model, {&model, &recoloured}, screen(540), LodParameters{}, 2);
    EXPECT_EQ(two.errors, one.errors);
}

// Far away a level is judged as an anti-aliased client shows it: the
// original moved by a fraction of a far pixel is nearly the original there,
// where one sample a pixel saw its edges jump from pixel to pixel.
TEST(ErrorByDistance, FarViewsAreSupersampled) {
    const Model model = test::lod_test_building();
    Model moved = model;
    for (Node& node : moved.nodes)
        for (Primitive& primitive : node.primitives)
            for (Eigen::Vector3f& position : primitive.positions)
                position += Eigen::Vector3f(0.03f, 0, 0.02f);
    const ErrorByDistance measured =
        measure_error_by_distance(model, {&moved}, screen(540), LodParameters{}, 2);
    const std::vector<double>& errors = measured.errors[0];
    // A fixed move matters less as the building shrinks (one sample: 0.029, 0.042, 0, 0.076, 0, 0.032 over
    // the last six distances).
    for (std::size_t d = 1; d < errors.size(); ++d) EXPECT_LE(errors[d], errors[d - 1] + 0.002) << d;
    EXPECT_LT(errors.back(), 0.01);
    EXPECT_GT(errors.front(), 0.03);  // near, the move is seen
}

// From the nearest distance on which the error stays within the threshold;
// never where it ends above it.
TEST(ErrorByDistance, SwitchDistancesFromKnownErrors) {
    const ErrorByDistance measured{
        {10, 20, 40, 80},
        {{0, 0, 0, 0}, {0.2, 0.04, 0.03, 0.01}, {0.01, 0.2, 0.04, 0.02}, {0.3, 0.2, 0.1, 0.06}}};
    EXPECT_EQ(switch_distances(measured, 0.05), (std::vector<double>{10, 20, 40, never}));
    EXPECT_EQ(switch_distances(measured, 0.25), (std::vector<double>{10, 10, 10, 20}));
}

// Each kept level switches in farther and costs less than the one before;
// the others are never needed.
TEST(ErrorByDistance, ReachableLevelsSwitchFartherAndCostLess) {
    // Switching in at once: the finer one is never drawn; a dearer one is never needed.
    EXPECT_EQ(reachable_levels({0, 10, 10, 20}, {100, 50, 40, 60}), (std::vector<std::size_t>{0, 2}));
    EXPECT_EQ(reachable_levels({0, 10, 20, 40}, {100, 50, 40, 30}), (std::vector<std::size_t>{0, 1, 2, 3}));
    EXPECT_EQ(reachable_levels({0, 10, never, 40}, {100, 50, 40, 30}), (std::vector<std::size_t>{0, 1, 3}));
    // A coarser level within the threshold nearer than a finer one takes its place.
    EXPECT_EQ(reachable_levels({0, 40, 20, 80}, {100, 50, 40, 30}), (std::vector<std::size_t>{0, 2, 3}));
    // A cheaper coarser level within the threshold nearer than a finer, dearer one is drawn first.
    EXPECT_EQ(reachable_levels({0, 10, 20, 5}, {100, 50, 10, 30}), (std::vector<std::size_t>{0, 3, 2}));
    // Level 0 is drawn from 0: a level within the threshold at the nearest distance switches in there.
    EXPECT_EQ(reachable_levels({10, 10, 20}, {100, 50, 40}), (std::vector<std::size_t>{0, 1, 2}));
}
