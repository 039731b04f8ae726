#include "toolkit/lod/pages/bake.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

using namespace boxlod;

TEST(Bake, OrientedBoxFacesHaveRightHandedUprightFrames) {
    OrientedBox box;
    box.center = {1, 2, 3};
    box.axes = Eigen::AngleAxisf(0.4f, Eigen::Vector3f::UnitY()).toRotationMatrix();
    box.half_extents = {1, 2, 3};
    auto faces = oriented_box_faces(box);
    for (int i = 0; i < 6; ++i) {
        const OrientedBoxFace& f = faces[i];
        EXPECT_NEAR(f.tangent.cross(f.bitangent).dot(f.normal), 1, 1e-6) << i;
        EXPECT_NEAR((f.center - box.center).dot(f.normal), box.half_extents[i / 2], 1e-5) << i;
        EXPECT_NEAR(f.half_depth, box.half_extents[i / 2], 1e-6);
    }
    // Walls (faces of axes 0 and 2) stand upright: bitangent = world up.
    for (int i : {0, 1, 4, 5}) EXPECT_NEAR(faces[i].bitangent.y(), 1, 1e-6) << i;
    EXPECT_NEAR(faces[0].half_height, 2, 1e-6);
    EXPECT_NEAR(faces[0].half_width, 3, 1e-6);
    // The top face looks up, its image up is world -Z (rotated with the box).
    EXPECT_NEAR(faces[2].normal.y(), 1, 1e-6);
    EXPECT_LT(faces[2].bitangent.z(), 0);
}

namespace {
// A red quad in the plane z = 0.5 across the whole unit box [0, 1]^3.
Model red_quad_model() {
    Model model;
    model.source = "quad";
    add_node(model, -1, "root");
    Primitive p;
    p.positions = {{0, 0, 0.5f}, {1, 0, 0.5f}, {1, 1, 0.5f}, {0, 1, 0.5f}};
    p.normals.assign(4, Eigen::Vector3f(0, 0, 1));
    p.indices = {0, 1, 2, 0, 2, 3};
    p.polygon_count = 1;
    p.material = 0;
    model.nodes[0].primitives.push_back(p);
    Material red;
    red.base_color = {1, 0, 0, 1};
    model.materials.push_back(red);
    return model;
}
}  // namespace

TEST(Bake, FaceRecordsAlbedoCoverageTangentNormalAndHeight) {
    Model model = red_quad_model();
    DecodedTextures textures = decode_textures(model);
    Drawable drawable = make_drawable(model, textures);
    OrientedBox box;
    box.center = {0.5f, 0.5f, 0.5f};
    box.half_extents = {0.5f, 0.5f, 0.5f};
    auto faces = oriented_box_faces(box);
    for (int f : {4, 5}) {  // +Z and -Z: the quad faces them, halfway into the box
        BakedFace baked = bake_face(drawable, faces[f], {16, 16}, 1);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                ASSERT_EQ(baked.color.at(x, y)[3], 255) << f << ": " << x << "," << y;
                EXPECT_EQ(baked.color.at(x, y)[0], 255);
                EXPECT_EQ(baked.color.at(x, y)[1], 0);
                EXPECT_EQ(baked.normal.at(x, y)[0], 128);
                EXPECT_EQ(baked.normal.at(x, y)[1], 128);
                EXPECT_EQ(baked.normal.at(x, y)[2], 255);          // facing the face: (0, 0, 1)
                EXPECT_NEAR(baked.height.at(x, y)[0], 32768, 40);  // halfway: height 0.5
            }
    }
    // Seen edge-on from +X the quad covers nothing: colour stays dilated-empty, normals (0,0,1), height 0.
    BakedFace side = bake_face(drawable, faces[0], {8, 8}, 1);
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_EQ(side.color.pixels[i * 4 + 3], 0);
        EXPECT_EQ(side.height.pixels[i], 0);
        EXPECT_EQ(side.normal.pixels[i * 3 + 2], 255);
    }
}

TEST(Bake, GlassIsCoveredOnlyWhereAtLeastHalfOpaqueAndRecordsItsAlbedo) {
    Model model = red_quad_model();
    Material glass;
    glass.base_color = {0, 0, 1, 0.25f};
    glass.alpha_mode = AlphaMode::blend;
    model.materials = {glass};
    DecodedTextures textures = decode_textures(model);
    OrientedBox box;
    box.center = {0.5f, 0.5f, 0.5f};
    box.half_extents = {0.5f, 0.5f, 0.5f};
    auto faces = oriented_box_faces(box);
    // Glass alone: see-through, so no texel is covered (the face's MASK cut-off is 0.5).
    BakedFace alone = bake_face(make_drawable(model, textures), faces[4], {8, 8}, 1);
    for (std::size_t i = 0; i < 64; ++i) EXPECT_EQ(alone.color.pixels[i * 4 + 3], 0) << i;
    // At alpha 0.75 it is covered, and the texel holds its own colour, not its colour over black.
    model.materials[0].base_color.w() = 0.75f;
    BakedFace opaque_enough = bake_face(make_drawable(model, textures), faces[4], {8, 8}, 1);
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_EQ(opaque_enough.color.pixels[i * 4 + 3], 255) << i;
        EXPECT_EQ(opaque_enough.color.pixels[i * 4 + 2], 255) << i;
    }
}

TEST(Bake, DilationFillsUncoveredTexelsFromTheNearestCovered) {
    Image8 color(5, 3, 4, 0);
    std::uint8_t* covered = color.at(0, 1);
    covered[0] = 200;
    covered[1] = 100;
    covered[2] = 50;
    covered[3] = 255;
    dilate_colors(color);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            EXPECT_EQ(color.at(x, y)[0], 200);
            EXPECT_EQ(color.at(x, y)[2], 50);
            EXPECT_EQ(color.at(x, y)[3], (x == 0 && y == 1) ? 255 : 0);  // coverage is kept
        }
}
