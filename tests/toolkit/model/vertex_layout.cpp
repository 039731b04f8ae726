#include "toolkit/model/vertex_layout.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// `vertices` vertices with every attribute, one triangle, material 0.
Model one_primitive(std::size_t vertices, Material material) {
    Model model;
    add_node(model, -1, "part");
    Primitive& p = model.nodes[0].primitives.emplace_back();
    p.positions.assign(vertices, Eigen::Vector3f::Zero());
    p.normals.assign(vertices, Eigen::Vector3f::UnitZ());
    p.uvs.assign(vertices, Eigen::Vector2f::Zero());
    p.tangents.assign(vertices, Eigen::Vector4f(1, 0, 0, 1));
    p.indices = {0, 1, std::uint32_t(vertices - 1)};
    p.material = 0;
    model.materials = {material};
    return model;
}

VertexLayout layout_of(const Model& model) { return vertex_layout(model.nodes[0].primitives[0], model); }

}  // namespace

TEST(VertexLayout, OnlyWhatTheMaterialSamplesIsWritten) {
    Material plain, coloured, mapped, specular;
    coloured.base_color_texture = 0;
    mapped.normal_texture = 0;
    specular.specular_texture = 0;
    VertexLayout a = layout_of(one_primitive(3, plain)), b = layout_of(one_primitive(3, coloured)),
                 c = layout_of(one_primitive(3, mapped)), d = layout_of(one_primitive(3, specular));
    EXPECT_TRUE(a.normals && !a.uvs && !a.tangents);
    EXPECT_TRUE(b.normals && b.uvs && !b.tangents);  // tangents only serve normal and height maps
    EXPECT_TRUE(c.uvs && c.tangents);
    EXPECT_TRUE(d.uvs && !d.tangents);
    Material height;
    height.height_texture = 0;
    EXPECT_TRUE(layout_of(one_primitive(3, height)).tangents);  // parallax needs the tangent frame
    // No material at all: nothing is sampled.
    Model none = one_primitive(3, plain);
    none.nodes[0].primitives[0].material = -1;
    EXPECT_FALSE(layout_of(none).uvs);
}

TEST(VertexLayout, SixteenBitIndicesUpTo65535Vertices) {
    // 65,535 vertices: the largest index is 65,534, below the reserved 65,535.
    EXPECT_EQ(layout_of(one_primitive(65535, {})).index_bytes, 2);
    EXPECT_EQ(layout_of(one_primitive(65536, {})).index_bytes, 4);
}

TEST(VertexLayout, MeshBytesHandComputed) {
    Material mapped;
    mapped.base_color_texture = 0;
    mapped.normal_texture = 1;
    Model model = one_primitive(4, mapped);
    EXPECT_EQ(primitive_mesh_bytes(model.nodes[0].primitives[0], model), 4u * (12 + 12 + 8 + 16) + 3 * 2);
    model = one_primitive(70000, {});
    EXPECT_EQ(primitive_mesh_bytes(model.nodes[0].primitives[0], model), 70000u * (12 + 12) + 3 * 4);
}
