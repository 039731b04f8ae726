#include "toolkit/lod/hybrid/baked_proxy.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

namespace {

// The unit box's faces baked at 64 x 64 texels, every texel covered, each face's
// surface `depth` metres in from its plane (height 1 - depth / 2: the box is 2 deep).
struct BakedBox {
    OrientedBox box{Eigen::Vector3f::Zero(), Eigen::Matrix3f::Identity(), Eigen::Vector3f::Ones()};
    std::array<BakedFace, 6> faces;

    explicit BakedBox(const std::array<float, 6>& depth) {
        for (std::size_t f = 0; f < 6; ++f) {
            faces[f].color = Image8(64, 64, 4, 255);
            faces[f].normal = Image8(64, 64, 3, 128);
            const auto height = std::uint16_t(std::lround((1 - depth[f] / 2) * 65535));
            faces[f].height = Image16(64, 64, 1, height);
            faces[f].covered = {0, 0, 64, 64};
        }
    }
    std::array<const BakedFace*, 6> pointers() const {
        return {&faces[0], &faces[1], &faces[2], &faces[3], &faces[4], &faces[5]};
    }
};

}  // namespace

// A triangle on the box's +X plane facing +X samples the +X face.
TEST(BakedProxy, ATriangleSamplesTheFaceItFaces) {
    const BakedBox baked({0, 0, 0, 0, 0, 0});
    const auto faces = oriented_box_faces(baked.box);
    EXPECT_EQ(sampled_face(faces, baked.pointers(), {1, -0.5f, -0.5f}, {1, 0.5f, -0.5f}, {1, 0, 0.5f}), 0);
    // Turned to face -Z, it samples the -Z face (the fifth: +a0, -a0, +a1, -a1, +a2, -a2).
    EXPECT_EQ(sampled_face(faces, baked.pointers(), {0, 0, -1}, {0.5f, 0.5f, -1}, {0.5f, -0.5f, -1}), 5);
    // A triangle of no area samples nothing.
    EXPECT_EQ(sampled_face(faces, baked.pointers(), {0, 0, 0}, {1, 0, 0}, {2, 0, 0}), -1);
}

// Facing +X more squarely than +Y, a triangle 0.1 m below the +Y plane and
// 0.5 m behind the +X plane samples +Y, whose bake saw a surface where it
// lies: +X's saw something in front of it (the depth check, not the angle).
TEST(BakedProxy, ATriangleSamplesTheFaceThatSawItNotTheOneItFacesMost) {
    const BakedBox baked({0, 0, 0.1f, 0, 0, 0});
    const auto faces = oriented_box_faces(baked.box);
    const Eigen::Vector3f normal = Eigen::Vector3f(0.8f, 0.6f, 0).normalized();
    const Eigen::Vector3f along = Eigen::Vector3f::UnitZ(), across = normal.cross(along);
    const Eigen::Vector3f centre(0.5f, 0.9f, 0);
    const Eigen::Vector3f a = centre - 0.05f * across + 0.05f * along, b = centre + 0.1f * across,
                          c = centre - 0.05f * across - 0.05f * along;
    ASSERT_GT((b - a).cross(c - a).dot(normal), 0);
    EXPECT_EQ(sampled_face(faces, baked.pointers(), a, b, c), 2);
    // Where neither face saw it (+Y's surface is far off too), the nearer surface decides: +X's at 0.5
    // against +Y's at 0.9.
    const BakedBox far({0, 0, 1.0f, 0, 0, 0});
    EXPECT_EQ(sampled_face(faces, far.pointers(), a, b, c), 0);
    // A face that saw nothing is never sampled.
    BakedBox empty({0, 0, 0.1f, 0, 0, 0});
    empty.faces[2].covered = {};
    EXPECT_EQ(sampled_face(faces, empty.pointers(), a, b, c), 0);
}

// A cube's twelve triangles split over the six faces, two each, in the faces'
// frames (the baked normal maps' tangent space) with uvs over the whole face.
TEST(BakedProxy, ACubeSamplesEachFaceWithTwoTrianglesInItsFrame) {
    Primitive cube;
    for (int k = 0; k < 8; ++k)
        cube.positions.emplace_back(k & 1 ? 1.f : -1.f, k & 2 ? 1.f : -1.f, k & 4 ? 1.f : -1.f);
    cube.indices = {1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2,   // +X, -X
                    2, 6, 7, 2, 7, 3, 0, 1, 5, 0, 5, 4,   // +Y, -Y
                    4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1};  // +Z, -Z
    cube.polygon_count = 12;
    const BakedBox baked({0, 0, 0, 0, 0, 0});
    const std::array<Primitive, 6> faces = baked_proxy_faces({cube}, baked.box, baked.pointers());
    const auto frames = oriented_box_faces(baked.box);
    for (std::size_t f = 0; f < 6; ++f) {
        const Primitive& q = faces[f];
        EXPECT_EQ(q.triangle_count(), 2u) << f;
        EXPECT_EQ(q.positions.size(), 4u) << f;  // the face's 4 corners, shared by its two triangles
        for (std::size_t v = 0; v < q.positions.size(); ++v) {
            EXPECT_TRUE(q.normals[v].isApprox(frames[f].normal)) << f;
            EXPECT_TRUE(q.tangents[v].head<3>().isApprox(frames[f].tangent)) << f;
            for (int i = 0; i < 2; ++i) EXPECT_TRUE(q.uvs[v][i] == 0 || q.uvs[v][i] == 1) << f;
        }
    }
    // The mesh: 24 vertices of 48 bytes and 36 16-bit indices.
    EXPECT_EQ(baked_proxy_mesh_bytes(faces), 24u * 48u + 36u * 2u);
}
