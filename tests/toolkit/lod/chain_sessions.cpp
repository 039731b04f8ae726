#include "toolkit/lod/chain_sessions.h"

#include "base/input_error.h"
#include "lod_scene.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace boxlod;

TEST(ChainSessions, AutoSizesEachLevelForTwiceTheLastDistance) {
    EXPECT_EQ(level_distances("auto", 10, 4), (std::vector<float>{10, 20, 40, 80}));
    EXPECT_EQ(level_distances("5,5,9", 10, 3), (std::vector<float>{5, 5, 9}));
    EXPECT_NE(test::input_error_of([] { level_distances("1,2,2e12", 10, 3); }).find("is not a distance in [0.001, 1e+12] m"),
              std::string::npos);
}

// A building in centimetres frames at some 10^4 units: its 10-level chain
// sized levels past 10^6, which their own parameters refused (exit 2 from
// `build --chain` on assimp's animation_with_skeleton.fbx, 7 km wide).
TEST(ChainSessions, ABuildingInCentimetresBuildsItsFarLevels) {
    Model model = test::lod_test_building();
    for (Node& node : model.nodes)
        for (Primitive& primitive : node.primitives)
            for (Eigen::Vector3f& position : primitive.positions) position *= 2000;
    LodParameters p;
    p.resolution = 64, p.min_texture_size = 16, p.max_texture_size = 64;
    ChainSessions sessions(model, p, 2);
    const float first = sessions.first->input.parameters.distance;
    ASSERT_GT(first * 512, 1e6f);
    sessions.distances = level_distances("auto", first, 10);
    EXPECT_FLOAT_EQ(sessions.distances.back(), first * 512);
    EXPECT_GT(sessions.for_level(10).input.parameters.distance, 1e6f);
    // 64 levels double past any range: the farthest stay at its end, still ascending.
    const std::vector<float> many = level_distances("auto", first, 64);
    EXPECT_EQ(double(many.back()), double(float(parameter_range::distance.max)));
    EXPECT_TRUE(std::is_sorted(many.begin(), many.end()));
}
