#include "toolkit/cgal/cgal_simplification.h"

#include "base/input_error.h"
#include "lod_scene.h"
#include "test_support.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

const Model& fzk_haus() {
    static const Model model = load_model(test::fzk_haus_ifc);
    return model;
}

}  // namespace

TEST(CgalSimplification, ReducesTheFzkHausKeepingMaterialsAndAttributes) {
    const std::size_t original = mesh_counts(fzk_haus()).triangles;
    Model simplified = cgal_simplify(fzk_haus(), original / 10);
    const std::size_t triangles = mesh_counts(simplified).triangles;
    EXPECT_LT(triangles, original / 4);  // CGAL stalls above the budget on separate parts, but it collapses
    EXPECT_GT(triangles, 0u);
    EXPECT_EQ(simplified.materials.size(), fzk_haus().materials.size());
    for (const Node& node : simplified.nodes)
        for (const Primitive& p : node.primitives) {
            ASSERT_GE(p.material, 0);
            EXPECT_LT(std::size_t(p.material), simplified.materials.size());
            EXPECT_EQ(p.normals.size(), p.positions.size());
            EXPECT_TRUE(p.uvs.empty() || p.uvs.size() == p.positions.size());
            for (std::size_t i = 0; i + 2 < p.indices.size();
                 i += 3) {  // flat: every corner has the face's normal
                const auto &a = p.positions[p.indices[i]], &b = p.positions[p.indices[i + 1]],
                           &c = p.positions[p.indices[i + 2]];
                Eigen::Vector3f face = (b - a).cross(c - a).normalized();
                for (int k = 0; k < 3; ++k)
                    EXPECT_GT(p.normals[p.indices[i + std::size_t(k)]].dot(face), 0.999f);
            }
        }
    validate_model(simplified);
}

TEST(CgalSimplification, IsDeterministicAndSharesEqualVertices) {
    Model a = cgal_simplify(fzk_haus(), 2000), b = cgal_simplify(fzk_haus(), 2000);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    std::size_t vertices = 0, corners = 0;
    for (std::size_t n = 0; n < a.nodes.size(); ++n)
        for (std::size_t p = 0; p < a.nodes[n].primitives.size(); ++p) {
            EXPECT_EQ(a.nodes[n].primitives[p].positions, b.nodes[n].primitives[p].positions);
            EXPECT_EQ(a.nodes[n].primitives[p].indices, b.nodes[n].primitives[p].indices);
            vertices += a.nodes[n].primitives[p].positions.size();
            corners += a.nodes[n].primitives[p].indices.size();
        }
    EXPECT_LT(vertices, corners);  // coplanar neighbours share their corners
}

TEST(CgalSimplification, BadInputIsAnInputError) {
    EXPECT_THROW(cgal_simplify(fzk_haus(), 0), InputError);
    Model lod = test::lod_test_building();
    lod.is_lod = true;
    EXPECT_THROW(cgal_simplify(lod, 10), InputError);
    Model empty;
    add_node(empty, -1, "root");
    EXPECT_THROW(cgal_simplify(empty, 10), InputError);
}
