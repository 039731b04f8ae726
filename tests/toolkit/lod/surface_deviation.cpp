#include "toolkit/lod/surface_deviation.h"

#include "lod_scene.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// A wall at z = 0 (x in [0, 2]) beside a step 1 m in front of it, at z = 1
// (x in [2, 4]), both facing +z, 2 m tall.
Model stepped_wall() {
    Model model;
    add_node(model, -1, "root");
    const int wall = test::add_part(model, 0, "wall", -1);
    test::add_quad(model.nodes[std::size_t(wall)].primitives[0], {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0});
    test::add_quad(model.nodes[std::size_t(wall)].primitives[0], {2, 0, 1}, {4, 0, 1}, {4, 2, 1}, {2, 2, 1});
    return model;
}

// The wall as a box's front face would draw it: one quad at the step's depth.
Model flattened_wall() {
    Model model;
    add_node(model, -1, "root");
    const int wall = test::add_part(model, 0, "wall", -1);
    test::add_quad(model.nodes[std::size_t(wall)].primitives[0], {0, 0, 1}, {4, 0, 1}, {4, 2, 1}, {0, 2, 1});
    return model;
}

// The wall's axis-aligned box (its minimal box would lie along the step's diagonal).
OrientedBox wall_frame() {
    OrientedBox frame;
    frame.center = {2, 1, 0.5f};
    frame.half_extents = {2, 1, 0.5f};
    return frame;
}

}  // namespace

TEST(SurfaceDeviation, IsTheDepthAFlattenedWallLoses) {
    const Model original = stepped_wall();
    const OrientedBox frame = wall_frame();
    const SurfaceViews views = surface_views(original, frame, 64);
    EXPECT_NEAR(surface_deviation(views, surface_views(flattened_wall(), frame, 64)), 1.0, 1e-4);
    EXPECT_EQ(surface_deviation(views, surface_views(original, frame, 64)), 0.0);
}

TEST(SurfaceDeviation, CountsOnlyWhatBothDraw) {
    // A level that drops the step draws nothing where it stood: no depth to compare there.
    const Model original = stepped_wall();
    Model wall_only = stepped_wall();
    Primitive& p = wall_only.nodes[1].primitives[0];
    p.positions.resize(4);
    p.normals.resize(4);
    p.uvs.resize(4);
    p.indices.resize(6);
    p.polygon_count = 1;
    const OrientedBox frame = wall_frame();
    EXPECT_EQ(surface_deviation(surface_views(original, frame, 64), surface_views(wall_only, frame, 64)),
              0.0);
}

TEST(SurfaceDeviation, MeasuresAlongTheFramesAxes) {
    // The same wall turned 30 degrees about y, measured in its own box: still 1 m.
    const Eigen::Matrix3f turn = Eigen::AngleAxisf(0.5235988f, Eigen::Vector3f::UnitY()).toRotationMatrix();
    Model original = stepped_wall(), level = flattened_wall();
    for (Model* model : {&original, &level})
        for (Eigen::Vector3f& v : model->nodes[1].primitives[0].positions) v = turn * v;
    OrientedBox frame = wall_frame();
    frame.center = turn * frame.center;
    frame.axes = turn * frame.axes;
    EXPECT_NEAR(surface_deviation(surface_views(original, frame, 64), surface_views(level, frame, 64)), 1.0,
                1e-4);
}
