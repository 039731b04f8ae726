#include "toolkit/model/statistics.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(Statistics, CountsFacesTrianglesVerticesAndBatchesPerMaterial) {
    Model model;
    add_node(model, -1, "root");
    int a = add_node(model, 0, "a");
    add_node(model, 0, "empty");
    model.materials.resize(2);
    Primitive quad;
    quad.positions = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.polygon_count = 1;
    quad.material = 1;
    model.nodes[a].primitives = {quad, quad};
    model.nodes[a].primitives[1].material = 0;
    model.nodes[0].primitives = {quad};
    model.nodes[0].primitives[0].positions[0].z() = -1.5f;

    KeyValues stats = model_statistics(model);
    auto value = [&](const std::string& key) { return value_of(stats, key); };
    EXPECT_EQ(value("nodes"), "3");
    EXPECT_EQ(value("nodes_with_geometry"), "2");
    EXPECT_EQ(value("depth"), "1");
    EXPECT_EQ(value("batches_original"), "2");
    EXPECT_EQ(value("faces_original"), "3");
    EXPECT_EQ(value("triangles_original"), "6");
    EXPECT_EQ(value("vertices_original"), "12");
    EXPECT_EQ(value("mesh_width"), "4");
    EXPECT_EQ(value("mesh_height"), "2");
    EXPECT_EQ(value("mesh_depth"), "1.5");
    // Three quads of 4 float positions and 6 16-bit indices, no textures (docs/design.md: Cost).
    EXPECT_EQ(value("draw_calls_original"), "2");
    EXPECT_EQ(value("mesh_bytes_original"), "180");
    EXPECT_EQ(value("texture_bytes_gpu_original"), "0");
    EXPECT_EQ(value("bytes_original"), "180");
}
