#include "experiments/sweep/single_box.h"

#include "lod_scene.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(SingleBox, IsSixQuadsAroundTheWholeModel) {
    Model building = test::lod_test_building();
    Model box = single_box_model(building);
    MeshCounts counts = mesh_counts(box);
    EXPECT_EQ(counts.faces, 6u);
    EXPECT_EQ(counts.triangles, 12u);
    EXPECT_NO_THROW(validate_model(box));
    Bounds inner = model_bounds(building), outer = model_bounds(box);
    EXPECT_TRUE((outer.min.array() <= inner.min.array() + 1e-4f).all());
    EXPECT_TRUE((outer.max.array() >= inner.max.array() - 1e-4f).all());
    // Outward normals: each face's normal points away from the box centre.
    const Primitive& quads = box.nodes[0].primitives[0];
    for (std::size_t i = 0; i < quads.positions.size(); ++i)
        EXPECT_GT(quads.normals[i].dot(quads.positions[i] - outer.center()), 0);
    // Counter-clockwise seen from outside: the winding agrees with the normal.
    for (std::size_t i = 0; i < quads.indices.size(); i += 3) {
        const auto &a = quads.positions[quads.indices[i]], &b = quads.positions[quads.indices[i + 1]],
                   &c = quads.positions[quads.indices[i + 2]];
        EXPECT_GT((b - a).cross(c - a).dot(quads.normals[quads.indices[i]]), 0);
    }
}

TEST(SingleBox, ColourIsTheAreaWeightedMean) {
    Model building = test::lod_test_building();
    for (Material& m : building.materials) m.base_color_texture = -1;
    // Ground 64 m2 of colour g, everything else white with weight w: keep only
    // two materials to know the answer.
    for (Node& node : building.nodes)
        for (Primitive& p : node.primitives) p.material = p.material == 0 ? 0 : 1;
    building.materials[1].base_color = {1, 1, 1, 1};
    double ground = 64, rest = 0;
    for (std::size_t n = 0; n < building.nodes.size(); ++n)
        for (const Primitive& p : building.nodes[n].primitives)
            if (p.material == 1)
                for (std::size_t i = 0; i < p.indices.size(); i += 3)
                    rest += 0.5 * double((p.positions[p.indices[i + 1]] - p.positions[p.indices[i]])
                                             .cross(p.positions[p.indices[i + 2]] - p.positions[p.indices[i]])
                                             .norm());
    Eigen::Vector3f color = single_box_model(building).materials[0].base_color.head<3>();
    Eigen::Vector3d expected =
        (ground * Eigen::Vector3d(0.4, 0.45, 0.35) + rest * Eigen::Vector3d::Ones()) / (ground + rest);
    EXPECT_NEAR(color.x(), expected.x(), 1e-5);
    EXPECT_NEAR(color.y(), expected.y(), 1e-5);
    EXPECT_NEAR(color.z(), expected.z(), 1e-5);
}

TEST(SingleBox, TextureDarkensTheColourByItsMean) {
    Model building = test::lod_test_building();
    Model plain = building;
    plain.materials[1].base_color_texture = -1;
    // The brick texture is darker than white: the textured walls pull the mean down.
    EXPECT_LT(single_box_model(building).materials[0].base_color.y(),
              single_box_model(plain).materials[0].base_color.y());
}
