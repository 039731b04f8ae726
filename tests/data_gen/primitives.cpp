#include "data_gen/primitives.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace boxlod {

namespace {

// Every triangle's winding agrees with its vertex normals (counter-clockwise seen from outside).
void expect_outward(const Primitive& primitive, const std::string& name) {
    for (std::size_t t = 0; t < primitive.indices.size(); t += 3) {
        const auto& p = primitive.positions;
        std::uint32_t a = primitive.indices[t], b = primitive.indices[t + 1], c = primitive.indices[t + 2];
        Eigen::Vector3f face = (p[b] - p[a]).cross(p[c] - p[a]);
        EXPECT_GT(face.dot(primitive.normals[a]), 0) << name << " triangle " << t / 3;
    }
}

// Every vertex lies inside the box [0, size].
void expect_inside(const Primitive& primitive, const Eigen::Vector3f& size) {
    for (const Eigen::Vector3f& p : primitive.positions) {
        EXPECT_TRUE((p.array() >= -1e-6f).all()) << p.transpose();
        EXPECT_TRUE((p.array() <= size.array() + 1e-6f).all()) << p.transpose();
    }
}

}  // namespace

TEST(ScopeFaces, OutwardFramesCoveringTheScope) {
    Eigen::Vector3f size(4, 3, 2);
    auto faces = scope_faces(size);
    const char* names[] = {"front", "right", "back", "left", "top", "bottom"};
    Eigen::Vector3f normals[] = {Eigen::Vector3f::UnitZ(),  Eigen::Vector3f::UnitX(),
                                 -Eigen::Vector3f::UnitZ(), -Eigen::Vector3f::UnitX(),
                                 Eigen::Vector3f::UnitY(),  -Eigen::Vector3f::UnitY()};
    float area = 0;
    for (int i = 0; i < 6; ++i) {
        EXPECT_STREQ(faces[i].name, names[i]);
        EXPECT_EQ(faces[i].u.cross(faces[i].v), normals[i]) << names[i];
        area += faces[i].width * faces[i].height;
        Eigen::Vector3f center =
            faces[i].origin + (faces[i].u * faces[i].width + faces[i].v * faces[i].height) / 2;
        EXPECT_LT((center - (size / 2 + normals[i].cwiseProduct(size) / 2)).norm(), 1e-6f) << names[i];
    }
    EXPECT_FLOAT_EQ(area, 2 * (4 * 3 + 4 * 2 + 3 * 2));
}

TEST(BuiltinPrimitive, PolygonCountsAndWinding) {
    Eigen::Vector3f size(4, 3, 2);
    struct Case {
        const char* name;
        std::size_t polygons, vertices, triangles;
    } cases[] = {{"box", 6, 24, 12},
                 {"quad", 1, 4, 2},
                 {"cylinder", 14, 72, 44},
                 {"gable", 5, 18, 8},
                 {"hip", 5, 18, 8}};
    for (const Case& c : cases) {
        Primitive primitive = builtin_primitive(c.name, size, 12);
        EXPECT_EQ(primitive.polygon_count, c.polygons) << c.name;
        EXPECT_EQ(primitive.positions.size(), c.vertices) << c.name;
        EXPECT_EQ(primitive.triangle_count(), c.triangles) << c.name;
        EXPECT_EQ(primitive.normals.size(), primitive.positions.size()) << c.name;
        EXPECT_EQ(primitive.tangents.size(), primitive.positions.size()) << c.name;
        expect_outward(primitive, c.name);
        expect_inside(primitive, size);
    }
    EXPECT_TRUE(is_builtin_primitive("hip"));
    EXPECT_FALSE(is_builtin_primitive("sphere"));
}

TEST(BuiltinPrimitive, HipRoofOnASquareIsAPyramid) {
    Primitive primitive = builtin_primitive("hip", {2, 1, 2});
    EXPECT_EQ(primitive.polygon_count, 5u);
    EXPECT_EQ(primitive.positions.size(), 16u);  // four triangles and the base
    expect_outward(primitive, "pyramid");
}

TEST(BuiltinPrimitive, DeepHipRoofTurnsItsRidge) {
    Primitive primitive = builtin_primitive("hip", {2, 1, 6});
    expect_inside(primitive, {2, 1, 6});
    expect_outward(primitive, "deep hip");
    for (const Eigen::Vector3f& p : primitive.positions) {
        if (p.y() == 1) {
            EXPECT_FLOAT_EQ(p.x(), 1);  // the ridge runs along z
        }
    }
}

TEST(BuiltinPrimitive, FlatScopeLeavesOutZeroAreaFaces) {
    EXPECT_EQ(builtin_primitive("box", {2, 0, 2}).polygon_count, 2u);
}

TEST(AddPolygon, SkipsDegeneratePolygons) {
    Primitive primitive;
    add_polygon(primitive, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
    add_polygon(primitive, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}});
    EXPECT_EQ(primitive.polygon_count, 0u);
    EXPECT_TRUE(primitive.positions.empty());
}

TEST(PlaceInWorld, MovesAndTurns) {
    Primitive primitive = builtin_primitive("quad", {2, 1, 0});
    ScopeBox scope;
    scope.origin = Eigen::Vector3f(10, 0, 0);
    scope.axes << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // x -> -z, z -> x
    place_in_world(primitive, scope);
    for (const Eigen::Vector3f& n : primitive.normals)
        EXPECT_LT((n - Eigen::Vector3f::UnitX()).norm(), 1e-6f);
    EXPECT_LT((primitive.positions[1] - Eigen::Vector3f(10, 0, -2)).norm(), 1e-6f);
}

TEST(PlanarTextureCoordinates, MetresOverTheTileSizeImageUpright) {
    Primitive primitive = builtin_primitive("quad", {2, 1, 0});
    planar_texture_coordinates(primitive, 0.5f);
    // Corners (0,0), (2,0), (2,1), (0,1): u grows to the right, v grows downwards.
    EXPECT_EQ(primitive.uvs[1], Eigen::Vector2f(4, 0));
    EXPECT_EQ(primitive.uvs[3], Eigen::Vector2f(0, -2));
}

}  // namespace boxlod
