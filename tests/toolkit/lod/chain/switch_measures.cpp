#include "toolkit/lod/chain/switch_measures.h"

#include "toolkit/formats/tileset.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

// A 3 x 4 x 12 box (diagonal 13, radius 6.5) seen with fovy 90 degrees: at
// distance 10 the view is H = 20 high, so the hand-computed values follow.
TEST(SwitchMeasures, EngineTermsFromTheSizingView) {
    Bounds bounds;
    bounds.add({0, 0, 0});
    bounds.add({3, 4, 12});
    TextureSizing view;
    view.fovy_degrees = 90;
    LodSwitch s = lod_switch(10, bounds, view);
    EXPECT_EQ(s.distance, 10);
    EXPECT_NEAR(s.unity_relative_height, 12.0 / 20, 1e-12);
    EXPECT_NEAR(s.unreal_screen_size, 13.0 / 20, 1e-12);
    EXPECT_NEAR(s.screen_coverage, M_PI * 6.5 * 6.5 / (16.0 / 9 * 400), 1e-12);
    // Twice as far: heights halve, areas quarter.
    LodSwitch far = lod_switch(20, bounds, view);
    EXPECT_NEAR(far.unity_relative_height, s.unity_relative_height / 2, 1e-12);
    EXPECT_NEAR(far.screen_coverage, s.screen_coverage / 4, 1e-12);
}

TEST(SwitchMeasures, ClientsRefineALevelNearerThanItsSwitchDistance) {
    TextureSizing view;
    view.fovy_degrees = 90;
    view.resolution = 100;
    const double error = level_geometric_error(50, view, 0.5);
    EXPECT_NEAR(error, 16, 1e-4);  // a pixel at 50 m is 2 x 50 x tan(45 degrees) / 100 = 1 m
    // CesiumJS's and 3d-tiles-renderer's projection of a tile's error on a screen as tall as the view.
    auto screen_space_error = [&](double distance) {
        return error * view.resolution / (2 * distance * std::tan(M_PI / 4));
    };
    EXPECT_GT(screen_space_error(49.5), client_screen_space_error);  // nearer: level c - 1
    EXPECT_LT(screen_space_error(50.5), client_screen_space_error);  // farther: level c stays
}

TEST(SwitchMeasures, ALevelWhoseLostDepthShowsRefinesFartherThanItsSwitchDistance) {
    TextureSizing view;
    view.fovy_degrees = 90;
    view.resolution = 100;
    // 16 pixels at 50 m are 16 m: a deviation of 40 m shows as 16 pixels at 125 m.
    EXPECT_NEAR(level_geometric_error(50, view, 40), 40, 1e-9);
    EXPECT_NEAR(level_geometric_error(50, view, 15.9), 16, 1e-4);
}
