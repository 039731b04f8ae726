#include "toolkit/lod/hybrid/draw_calls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

using namespace boxlod;

namespace {

// A unit quad at height z as two triangles with their own corners (unwelded,
// as a box face or an importer's part arrives).
Primitive quad(float x, float z, int material, bool with_uvs) {
    Primitive p;
    p.positions = {{x, 0, z}, {x + 1, 0, z}, {x + 1, 1, z}, {x, 0, z}, {x + 1, 1, z}, {x, 1, z}};
    if (with_uvs)  // planar: parts side by side agree on a shared edge
        for (const Eigen::Vector3f& corner : p.positions) p.uvs.push_back(corner.head<2>());
    p.indices = {0, 1, 2, 3, 4, 5};
    p.polygon_count = 1;
    p.material = material;
    return p;
}

using Triangle = std::array<float, 10>;  // material, then three corners

std::vector<Triangle> triangles(const Model& model) {
    std::vector<Triangle> out;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives)
            for (std::size_t t = 0; t < p.indices.size(); t += 3) {
                Triangle triangle{float(p.material)};
                for (int k = 0; k < 3; ++k)
                    for (int a = 0; a < 3; ++a)
                        triangle[std::size_t(1 + 3 * k + a)] = p.positions[p.indices[t + std::size_t(k)]][a];
                out.push_back(triangle);
            }
    std::sort(out.begin(), out.end());
    return out;
}

Model level_of_parts() {
    Model model;
    model.materials = {Material{"brick"}, Material{"page_0"},
                       Material{"brick"}};  // 2: an importer's copy of 0
    model.is_lod = true;
    model.lod_params = {{"level", "3"}};
    model.source = "house.glb";
    int root = add_node(model, -1, "house");
    int wall = add_node(model, root, "wall");
    model.nodes[std::size_t(add_node(model, wall, "left"))].primitives.push_back(quad(0, 0, 0, true));
    model.nodes[std::size_t(add_node(model, wall, "right"))].primitives.push_back(
        quad(1, 0, 2, true));  // shares an edge
    model.nodes[std::size_t(add_node(model, root, "box"))].primitives.push_back(quad(0, 1, 1, true));
    return model;
}

}  // namespace

TEST(DrawCalls, ALevelBecomesOneNodePerMaterialDrawingTheSameTriangles) {
    const Model level = level_of_parts();
    const Model merged = merge_draw_calls(level, "house_L3");
    ASSERT_EQ(merged.nodes.size(), 3u);  // the root and one node per distinct material
    EXPECT_EQ(merged.nodes[0].name, "house_L3");
    EXPECT_EQ(merged.nodes[0].children, (std::vector<int>{1, 2}));
    EXPECT_EQ(merged.nodes[1].name, "brick");
    EXPECT_EQ(merged.nodes[2].name, "page_0");
    ASSERT_EQ(merged.materials.size(), 2u);
    for (int n : {1, 2}) ASSERT_EQ(merged.nodes[std::size_t(n)].primitives.size(), 1u);
    const Primitive& brick = merged.nodes[1].primitives[0];
    EXPECT_EQ(brick.material, 0);
    EXPECT_EQ(brick.polygon_count, 2u);
    EXPECT_EQ(brick.triangle_count(), 4u);
    // Welded: the 2x1 wall has 6 distinct corners (12 as read), the edge they share counted once.
    EXPECT_EQ(brick.positions.size(), 6u);
    EXPECT_EQ(brick.uvs.size(), 6u);
    EXPECT_EQ(merged.nodes[2].primitives[0].material, 1);
    // The same triangles, with the copy's material now the one it equals.
    Model expected = level;
    expected.nodes[3].primitives[0].material = 0;
    EXPECT_EQ(triangles(merged), triangles(expected));
    EXPECT_TRUE(merged.is_lod);
    EXPECT_EQ(merged.lod_params, level.lod_params);
    EXPECT_EQ(merged.source, "house.glb");
}

TEST(DrawCalls, PartsWithOtherAttributesStayApartAndNotWeldedAcrossAttributes) {
    Model model;
    model.materials = {Material{"plaster"}};
    int root = add_node(model, -1, "root");
    model.nodes[std::size_t(add_node(model, root, "textured"))].primitives.push_back(quad(0, 0, 0, true));
    model.nodes[std::size_t(add_node(model, root, "plain"))].primitives.push_back(quad(0, 0, 0, false));
    const std::vector<Primitive> merged = merge_primitives(model, {1, 2});
    ASSERT_EQ(merged.size(), 2u);  // one vertex layout each
    EXPECT_EQ(merged[0].uvs.size(), 6u);
    EXPECT_TRUE(merged[1].uvs.empty());
    Primitive textured = merged[0];
    textured.uvs[3] = {0.5f, 0.5f};  // the corner at (0,0) once more, with another uv
    weld(textured);
    EXPECT_EQ(textured.positions.size(), 5u);  // four corners, one of them twice: its uvs differ
}
