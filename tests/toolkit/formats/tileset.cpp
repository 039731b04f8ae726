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

TEST(Tileset, ClientsRefineALevelNearerThanItsSwitchDistance) {
    TextureSizing view;
    view.fovy_degrees = 90;
    view.resolution = 100;
    const double error = level_geometric_error(50, view, 0.5);
    EXPECT_NEAR(error, 16, 1e-4);  // a pixel at 50 m is 2 x 50 x tan(45 degrees) / 100 = 1 m
    // CesiumJS's and 3d-tiles-renderer's projection of a tile's error on a screen as tall as the view.
    auto screen_space_error = [&](double distance) { return error * view.resolution / (2 * distance * std::tan(M_PI / 4)); };
    EXPECT_GT(screen_space_error(49.5), client_screen_space_error);  // nearer: level c - 1
    EXPECT_LT(screen_space_error(50.5), client_screen_space_error);  // farther: level c stays
}

TEST(Tileset, ALevelWhoseLostDepthShowsRefinesFartherThanItsSwitchDistance) {
    TextureSizing view;
    view.fovy_degrees = 90;
    view.resolution = 100;
    // 16 pixels at 50 m are 16 m: a deviation of 40 m shows as 16 pixels at 125 m.
    EXPECT_NEAR(level_geometric_error(50, view, 40), 40, 1e-9);
    EXPECT_NEAR(level_geometric_error(50, view, 15.9), 16, 1e-4);
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
    EXPECT_EQ(nlohmann::json::parse(tileset_json({house, shed}, {}))["root"]["geometricError"].get<double>(), 20.0);
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
    std::vector<std::pair<std::string, double>> expected{{"h_L2.glb", 0.5}, {"h_L1.glb", 0.5}, {"h_L0.glb", 0}};
    EXPECT_EQ(chain, expected);
    EXPECT_EQ(root["children"][0]["extras"]["name"], "house");
    house.levels[2].surface_deviation = 0.25;  // each tile states its measured deviation
    const nlohmann::json again = nlohmann::json::parse(tileset_json({house}, {}))["root"]["children"][0];
    EXPECT_EQ(again["extras"]["boxlod"]["surface_deviation"], 0.25);
    EXPECT_EQ(again["children"][0]["extras"]["boxlod"]["surface_deviation"], 0);
    EXPECT_EQ(root["children"][1]["content"]["uri"], "s_L1.glb");
}
