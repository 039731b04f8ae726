#include "toolkit/model/model.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

namespace {
Primitive triangle() {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    p.polygon_count = 1;
    return p;
}
}  // namespace

TEST(Model, AddNodeLinksParentAndChild) {
    Model model;
    int root = add_node(model, -1, "root");
    int a = add_node(model, root, "a");
    int b = add_node(model, a, "b");
    EXPECT_EQ(model.nodes[root].children, std::vector<int>{a});
    EXPECT_EQ(model.nodes[b].parent, a);
}

TEST(Model, DepthCountsEdgesOfTheLongestPath) {
    Model model;
    add_node(model, -1, "root");
    EXPECT_EQ(tree_depth(model), 0);
    int a = add_node(model, 0, "a");
    add_node(model, 0, "b");
    add_node(model, add_node(model, a, "c"), "d");
    EXPECT_EQ(tree_depth(model), 3);
}

TEST(Model, BoundsCoverAllGeometry) {
    Model model;
    add_node(model, -1, "root");
    model.nodes[0].primitives.push_back(triangle());
    model.nodes[0].primitives[0].positions[2] = {-2, 5, 3};
    Bounds bounds = model_bounds(model);
    EXPECT_EQ(bounds.min, Eigen::Vector3f(-2, 0, 0));
    EXPECT_EQ(bounds.max, Eigen::Vector3f(1, 5, 3));
    EXPECT_EQ(bounds.size(), Eigen::Vector3f(3, 5, 3));
}

TEST(Model, ValidationRejectsEachKindOfBadData) {
    auto valid = [] {
        Model model;
        model.source = "m.gltf";
        add_node(model, -1, "root");
        model.nodes[0].primitives.push_back(triangle());
        return model;
    };
    EXPECT_NO_THROW(validate_model(valid()));

    Model out_of_range = valid();
    out_of_range.nodes[0].primitives[0].indices[1] = 3;
    EXPECT_THROW(validate_model(out_of_range), InputError);

    Model nan = valid();
    nan.nodes[0].primitives[0].positions[0].x() = std::nanf("");
    EXPECT_THROW(validate_model(nan), InputError);

    Model infinite = valid();
    infinite.nodes[0].primitives[0].positions[0].y() = std::numeric_limits<float>::infinity();
    EXPECT_THROW(validate_model(infinite), InputError);

    Model empty;
    empty.source = "m.gltf";
    add_node(empty, -1, "root");
    EXPECT_THROW(validate_model(empty), InputError);

    Model zero_area = valid();  // e.g. random bytes that assimp reads as one point
    for (auto& p : zero_area.nodes[0].primitives[0].positions) p = Eigen::Vector3f(1, 2, 3);
    EXPECT_THROW(validate_model(zero_area), InputError);

    Model bad_material = valid();
    bad_material.nodes[0].primitives[0].material = 0;
    EXPECT_THROW(validate_model(bad_material), InputError);

    // Colours are glTF's factors, each in [0, 1] (a reader of other formats clamps them).
    Model bright = valid();
    bright.materials.push_back({});
    bright.materials[0].name = "lamp";
    bright.nodes[0].primitives[0].material = 0;
    EXPECT_NO_THROW(validate_model(bright));
    bright.materials[0].base_color = {1.5f, 0, 0, 1};
    auto message_of = [](const Model& model) {
        try {
            validate_model(model);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_EQ(message_of(bright), "m.gltf: material 'lamp': base colour (1.5, 0, 0, 1) out of range [0, 1]");
    bright.materials[0].base_color = {1, 1, 1, 1};
    bright.materials[0].specular_color = {0, -0.25f, 0};
    EXPECT_EQ(message_of(bright),
              "m.gltf: material 'lamp': specular colour (0, -0.25, 0) out of range [0, 1]");

    // Coordinates beyond any model's (a glTF node scaled by 1e30): the distances framing it would overflow.
    Model far = valid();
    far.nodes[0].primitives[0].positions[1].z() = 1e9f;
    EXPECT_NO_THROW(validate_model(far));
    far.nodes[0].primitives[0].positions[1].z() = -2e9f;
    EXPECT_EQ(
        message_of(far),
        "m.gltf: node 0 'root' primitive 0: a position (1, 0, -2e+09) outside [-1000000000, 1000000000]");

    try {
        validate_model(out_of_range);
    } catch (const InputError& error) {
        std::string message = error.what();
        EXPECT_NE(message.find("m.gltf"), std::string::npos);
        EXPECT_NE(message.find("out of range"), std::string::npos);
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST(Model, NormalsAndTangentsBecomeUnitOrAreDropped) {
    Model model;
    add_node(model, -1, "root");
    Primitive scaled = triangle(), zero = triangle();
    scaled.normals = {{0, 0, 2}, {0, 0, 0.5f}, {3, 0, 4}};
    scaled.tangents = {{2, 0, 0, 0.3f}, {1, 0, 0, -7}, {0, 4, 0, 1}};
    zero.normals = {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}};  // glTF-Sample-Models' BoxBadNormals
    zero.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {0, 0, 0, 1}};
    model.nodes[0].primitives = {scaled, zero};
    make_unit_normals_and_tangents(model);
    const Primitive &a = model.nodes[0].primitives[0], &b = model.nodes[0].primitives[1];
    EXPECT_EQ(a.normals, (std::vector<Eigen::Vector3f>{{0, 0, 1}, {0, 0, 1}, {0.6f, 0, 0.8f}}));
    EXPECT_EQ(a.tangents, (std::vector<Eigen::Vector4f>{{1, 0, 0, 1}, {1, 0, 0, -1}, {0, 1, 0, 1}}));
    EXPECT_TRUE(b.normals.empty());   // drawn flat
    EXPECT_TRUE(b.tangents.empty());  // unmapped
    // What is not finite is left for validate_model to refuse.
    model.nodes[0].primitives[0].normals[0].x() = std::nanf("");
    make_unit_normals_and_tangents(model);
    EXPECT_THROW(validate_model(model), InputError);
}

TEST(Model, DrawsAnythingUnlessEverySurfaceIsFullyTransparent) {
    Model model;
    add_node(model, -1, "root");
    model.nodes[0].primitives = {triangle()};
    EXPECT_TRUE(draws_anything(model));  // no material: the default, opaque
    Material clear;
    clear.alpha_mode = AlphaMode::blend;
    clear.base_color.w() = 0;
    model.materials = {clear};
    model.nodes[0].primitives[0].material = 0;
    EXPECT_FALSE(draws_anything(model));
    model.materials[0].alpha_mode = AlphaMode::opaque;  // alpha ignored
    EXPECT_TRUE(draws_anything(model));
    model.materials[0].alpha_mode = AlphaMode::mask;
    EXPECT_FALSE(draws_anything(model));
    model.materials[0].base_color.w() = 0.2f;
    EXPECT_TRUE(draws_anything(model));
}

// What a chain compares its levels by: the picture, not the names or the tree.
TEST(Model, DrawsTheSameWithTheSamePrimitivesMaterialsAndTexels) {
    Model a;
    add_node(a, -1, "root");
    add_node(a, 0, "part");
    a.nodes[1].primitives = {triangle()};
    a.materials = {Material{}};
    a.nodes[1].primitives[0].material = 0;
    a.textures = {Texture{"a_L1_color_0.png", Image8(2, 2, 3), {}, Wrap::clamp}};
    a.materials[0].base_color_texture = 0;
    Model b = a;
    b.nodes[0].name = "other";
    b.textures[0].name = "a_L2_color_0.png";
    add_node(b, 0, "empty");
    EXPECT_TRUE(draws_the_same(a, b));
    b.nodes[1].primitives[0].positions[2].z() = 1e-6f;
    EXPECT_FALSE(draws_the_same(a, b));
    b = a;
    b.textures[0].image.pixels[3] = 1;
    EXPECT_FALSE(draws_the_same(a, b));
    b = a;
    b.materials[0].base_color.x() = 0.5f;
    EXPECT_FALSE(draws_the_same(a, b));
    b = a;  // one triangle more, on the root
    b.nodes[0].primitives = {triangle()};
    EXPECT_FALSE(draws_the_same(a, b));
}
