#include "toolkit/formats/tileset.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace boxlod;

TEST(Tileset, BoxesTurnFromYUpToZUp) {
    OrientedBox box;
    box.center = {1, 2, 3};
    box.half_extents = {1, 2, 0};  // flat: kept 1 cm thick
    std::array<double, 12> b = tile_box(box);
    std::array<double, 12> expected{1, -3, 2, 1, 0, 0, 0, 0, 2, 0, -0.01, 0};
    for (std::size_t i = 0; i < 12; ++i) EXPECT_NEAR(b[i], expected[i], 1e-12) << i;
}

TEST(Tileset, EastNorthUpFrameOnTheEllipsoid) {
    // On the equator at longitude 0: east +Y, north +Z, up +X, origin on the semi-major axis.
    std::array<double, 16> m = east_north_up_to_ecef({0, 0, 0});
    std::array<double, 16> expected{0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 6378137, 0, 0, 1};
    for (std::size_t i = 0; i < 16; ++i) EXPECT_NEAR(m[i], expected[i], 1e-9) << i;
    // At the pole the origin lies on the semi-minor axis b = a (1 - f) = 6,356,752.3142 m, 100 m higher.
    std::array<double, 16> pole = east_north_up_to_ecef({90, 0, 100});
    EXPECT_NEAR(pole[14], 6356752.3142 + 100, 1e-3);
    EXPECT_NEAR(pole[12], 0, 1e-6);
}

// A map grid's north 90 degrees east of true north: the model's +y points east, its +x south.
TEST(Tileset, TheFrameTurnsByItsHeading) {
    Geodetic at{0, 0, 0};
    at.heading_degrees = 90;
    const std::array<double, 16> m = east_north_up_to_ecef(at);
    std::array<double, 16> expected{0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 6378137, 0, 0, 1};
    for (std::size_t i = 0; i < 16; ++i) EXPECT_NEAR(m[i], expected[i], 1e-9) << i;
}

TEST(Tileset, EachObjectIsAChainOfReplacingTilesCoarsestFirst) {
    OrientedBox box;
    box.half_extents = {1, 1, 1};
    TileObject house{"house", box, {{"h_L0.glb", 0}, {"h_L1.glb", 0.5}, {"h_L2.glb", 0.2}}};
    box.center = {10, 0, 0};
    TileObject shed{"shed", box, {{"s_L0.glb", 0}, {"s_L1.glb", 1}}};
    nlohmann::json tileset = nlohmann::json::parse(tileset_json({house, shed}, {}));
    EXPECT_EQ(tileset["asset"]["version"], "1.1");
    const nlohmann::json& root = tileset["root"];
    EXPECT_EQ(root["refine"], "ADD");
    EXPECT_FALSE(root.contains("content"));
    EXPECT_EQ(root["transform"].size(), 16u);
    ASSERT_EQ(root["children"].size(), 2u);
    EXPECT_GE(root["geometricError"].get<double>(), 11.0);  // the city's diameter: 12 x 2 x 2 m of boxes
    EXPECT_LT(root["geometricError"].get<double>(), 13.0);
    shed.levels[1].geometric_error = 10;  // a coarsest level drawn up to twice its switch distance
    EXPECT_EQ(nlohmann::json::parse(tileset_json({house, shed}, {}))["root"]["geometricError"].get<double>(),
              20.0);
    // house: L2 (error raised to L1's 0.5) > L1 > L0, each replacing its parent.
    const nlohmann::json* tile = &root["children"][0];
    std::vector<std::pair<std::string, double>> chain;
    while (true) {
        chain.emplace_back((*tile)["content"]["uri"], (*tile)["geometricError"]);
        EXPECT_EQ((*tile)["boundingVolume"]["box"].size(), 12u);
        if (!tile->contains("children")) break;
        EXPECT_EQ((*tile)["refine"], "REPLACE");
        ASSERT_EQ((*tile)["children"].size(), 1u);
        tile = &(*tile)["children"][0];
    }
    std::vector<std::pair<std::string, double>> expected{
        {"h_L2.glb", 0.5}, {"h_L1.glb", 0.5}, {"h_L0.glb", 0}};
    EXPECT_EQ(chain, expected);
    EXPECT_EQ(root["children"][0]["extras"]["name"], "house");
    house.levels[2].surface_deviation = 0.25;  // each tile states its measured deviation
    const nlohmann::json again = nlohmann::json::parse(tileset_json({house}, {}))["root"]["children"][0];
    EXPECT_EQ(again["extras"]["boxlod"]["surface_deviation"], 0.25);
    EXPECT_EQ(again["children"][0]["extras"]["boxlod"]["surface_deviation"], 0);
    EXPECT_EQ(root["children"][1]["content"]["uri"], "s_L1.glb");
}
