#include "experiments/sweep/impostor.h"

#include "lod_scene.h"
#include "toolkit/drawing/drawable.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// The test building seen orthographically along `direction` through a window of
// half-size `half` around `center`, in albedo mode (what the atlas records).
Frame albedo_view(const Model& model, const Eigen::Vector3f& direction, const Eigen::Vector3f& center,
                  float half, const Eigen::Vector3f& up) {
    auto drawable = make_drawable_model(model);
    RenderSettings settings;
    settings.mode = RenderMode::albedo;
    settings.threads = 1;
    Camera& camera = settings.camera;
    camera.orthographic = true;
    camera.position = center + direction * (4 * half);
    camera.target = center;
    camera.up = up;
    camera.left = camera.bottom = -half;
    camera.right = camera.top = half;
    camera.near_plane = half;
    camera.far_plane = 8 * half;
    Frame frame = make_frame(64, 64, {0, 0, 0});
    render(drawable->drawable.batches, settings, frame);
    return frame;
}

}  // namespace

TEST(Impostor, HemiOctahedralDirectionsCoverTheUpperHemisphere) {
    EXPECT_TRUE(hemi_octahedral_direction({0, 0}).isApprox(Eigen::Vector3f(0, 1, 0)));
    for (Eigen::Vector2f corner :
         {Eigen::Vector2f(1, 1), Eigen::Vector2f(-1, 1), Eigen::Vector2f(1, -1), Eigen::Vector2f(-1, -1)})
        EXPECT_NEAR(hemi_octahedral_direction(corner).y(), 0,
                    1e-6);  // the square's corners lie on the horizon
    for (float x = -1; x <= 1; x += 0.25f)
        for (float y = -1; y <= 1; y += 0.25f) {
            Eigen::Vector3f d = hemi_octahedral_direction({x, y});
            EXPECT_NEAR(d.norm(), 1, 1e-6);
            EXPECT_GE(d.y(), 0);
        }
}

TEST(Impostor, EachCellIsTheModelSeenFromItsDirection) {
    Model building = test::lod_test_building();
    ImpostorAtlas atlas = make_impostor(building, 4, 64, 2);
    ASSERT_EQ(atlas.frames.size(), 16u);
    EXPECT_EQ(atlas.color.width, 4 * 64);
    for (int i : {5, 10, 15}) {  // the quad drawn from far along a direction, against the model from there
        const OrientedBoxFace& f = atlas.frames[std::size_t(i)];
        Eigen::Vector3f eye = f.center + f.normal * 100;
        EXPECT_EQ(nearest_direction(atlas, eye), i);
        Model quad = impostor_model(atlas, eye, "test");
        ASSERT_EQ(quad.nodes[0].primitives.size(), 1u);
        EXPECT_EQ(quad.nodes[0].primitives[0].triangle_count(), 2u);
        EXPECT_TRUE(quad.nodes[0].primitives[0].normals[0].isApprox(f.normal));
        Frame a = albedo_view(building, f.normal, f.center, f.half_width, f.bitangent);
        Frame b = albedo_view(quad, f.normal, f.center, f.half_width, f.bitangent);
        std::size_t both = 0, either = 0;
        double difference = 0;
        for (std::size_t p = 0; p < a.color.size(); ++p) {
            bool x = a.color[p].w() > 0, y = b.color[p].w() > 0;
            both += x && y;
            either += x || y;
            if (x && y) difference += (a.color[p] - b.color[p]).head<3>().cwiseAbs().sum() / 3;
        }
        ASSERT_GT(both, 200u);
        EXPECT_GT(double(both) / double(either), 0.95) << i;  // the same silhouette
        EXPECT_LT(difference / double(both), 0.03) << i;      // and colours
    }
}

TEST(Impostor, CellsHoldTheSphereAtTexelSize) {
    Bounds bounds;
    bounds.add({0, 0, 0});
    bounds.add({3, 4, 0});  // diameter 5
    EXPECT_EQ(impostor_cell(bounds, 0.1), 50 + 4);
    EXPECT_EQ(impostor_cell(bounds, 10), 8);
    EXPECT_EQ(impostor_cell(bounds, 1e-6), 2048);
    EXPECT_THROW(make_impostor(test::lod_test_building(), 1, 64, 1), std::invalid_argument);
}
