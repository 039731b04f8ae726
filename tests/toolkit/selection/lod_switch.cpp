#include "toolkit/selection/lod_switch.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

// A 3 x 4 x 12 box (diagonal 13, radius 6.5) seen with fovy 90 degrees: at
// distance 10 the view is H = 20 high, so the hand-computed values follow.
TEST(LodSwitch, EngineTermsFromTheSizingView) {
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
