#include "data_gen/interpreter.h"

#include "base/input_error.h"
#include "base/memory_budget.h"
#include "data_gen/grammar_parser.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace boxlod {

namespace {

Model build(const std::string& text, float width, float depth, std::uint64_t seed = 0,
            const std::string& start = "", DerivationLimits limits = {}) {
    Grammar grammar = parse_grammar(text, "g.grammar");
    BuildingOptions options;
    options.start = start;
    options.lot = Eigen::Vector2f(width, depth);
    options.seed = seed;
    options.limits = limits;
    return generate_building(grammar, options);
}

std::string build_error(const std::string& text, float width = 4, float depth = 2,
                        DerivationLimits limits = {}) {
    try {
        build(text, width, depth, 0, "", limits);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

void expect_scope(const Node& node, Eigen::Vector3f center, Eigen::Vector3f half_extents,
                  Eigen::Matrix3f axes = Eigen::Matrix3f::Identity()) {
    ASSERT_TRUE(node.scope.has_value()) << node.name;
    EXPECT_LT((node.scope->center - center).norm(), 1e-5f)
        << node.name << " center " << node.scope->center.transpose() << " expected " << center.transpose();
    EXPECT_LT((node.scope->half_extents - half_extents).norm(), 1e-5f)
        << node.name << " half extents " << node.scope->half_extents.transpose();
    EXPECT_LT((node.scope->axes - axes).norm(), 1e-5f) << node.name << " axes\n" << node.scope->axes;
}

std::vector<std::string> rules(const Model& model) {
    std::vector<std::string> out;
    for (const Node& node : model.nodes) out.push_back(node.rule);
    return out;
}

Bounds node_bounds(const Node& node) {
    Bounds bounds;
    for (const Primitive& primitive : node.primitives)
        for (const Eigen::Vector3f& p : primitive.positions) bounds.add(p);
    return bounds;
}

}  // namespace

TEST(Interpreter, ExtrudeAndSplitMakeTheDerivationTree) {
    Model model =
        build("Lot --> extrude(3) Mass\nMass --> split(x) { 1 : A | ~1 : B }\nA --> i(box)\nB -->\n", 4, 2);
    ASSERT_EQ(rules(model), (std::vector<std::string>{"Lot", "Mass", "A", "B"}));
    EXPECT_EQ(model.nodes[0].parent, -1);
    EXPECT_EQ(model.nodes[1].parent, 0);
    EXPECT_EQ(model.nodes[2].parent, 1);
    EXPECT_EQ(model.nodes[3].parent, 1);
    EXPECT_EQ(model.nodes[1].children, (std::vector<int>{2, 3}));
    EXPECT_EQ(model.nodes[2].name, "A");
    expect_scope(model.nodes[0], {0, 0, 0}, {2, 0, 1});
    expect_scope(model.nodes[1], {0, 1.5f, 0}, {2, 1.5f, 1});
    expect_scope(model.nodes[2], {-1.5f, 1.5f, 0}, {0.5f, 1.5f, 1});
    expect_scope(model.nodes[3], {0.5f, 1.5f, 0}, {1.5f, 1.5f, 1});
    EXPECT_FALSE(model.nodes[0].has_geometry());
    ASSERT_EQ(model.nodes[2].primitives.size(), 1u);
    const Primitive& box = model.nodes[2].primitives[0];
    EXPECT_EQ(box.polygon_count, 6u);
    EXPECT_EQ(box.positions.size(), 24u);
    EXPECT_EQ(box.triangle_count(), 12u);
    EXPECT_EQ(box.uvs.size(), 24u);
    EXPECT_EQ(box.tangents.size(), 24u);
    Bounds bounds = node_bounds(model.nodes[2]);
    EXPECT_LT((bounds.min - Eigen::Vector3f(-2, 0, -1)).norm(), 1e-6f);
    EXPECT_LT((bounds.max - Eigen::Vector3f(-1, 3, 1)).norm(), 1e-6f);
    EXPECT_NO_THROW(validate_model(model));
}

TEST(Interpreter, ComponentSplitGivesFaceScopes) {
    Model model = build(
        "M --> extrude(2) comp(f) { front : F | side : S | top : T }\nF --> i(quad)\nS -->\nT -->\n", 4, 2);
    ASSERT_EQ(rules(model), (std::vector<std::string>{"M", "F", "S", "S", "T"}));
    expect_scope(model.nodes[1], {0, 1, 1}, {2, 1, 0});
    Eigen::Matrix3f right;
    right << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // columns: -z, y, x
    expect_scope(model.nodes[2], {2, 1, 0}, {1, 1, 0}, right);
    Eigen::Matrix3f left;
    left << 0, 0, -1, 0, 1, 0, 1, 0, 0;  // columns: z, y, -x
    expect_scope(model.nodes[3], {-2, 1, 0}, {1, 1, 0}, left);
    Eigen::Matrix3f top;
    top << 1, 0, 0, 0, 0, 1, 0, -1, 0;  // columns: x, -z, y
    expect_scope(model.nodes[4], {0, 2, 0}, {2, 1, 0}, top);
    const Primitive& quad = model.nodes[1].primitives[0];
    EXPECT_EQ(quad.polygon_count, 1u);
    for (std::size_t i = 0; i < quad.positions.size(); ++i) {
        EXPECT_FLOAT_EQ(quad.positions[i].z(), 1);
        EXPECT_LT((quad.normals[i] - Eigen::Vector3f::UnitZ()).norm(), 1e-6f);
    }
}

TEST(Interpreter, ScopeOperationsPushAndCenter) {
    Model model = build(
        "A --> extrude(2) [ s(1, 1, 1) center(xz) B ] t('0.5, 0, 1) C r(0, 90, 0) D\nB -->\nC -->\nD -->\n",
        4, 2);
    ASSERT_EQ(rules(model), (std::vector<std::string>{"A", "B", "C", "D"}));
    expect_scope(model.nodes[1], {0, 0.5f, 0}, {0.5f, 0.5f, 0.5f});
    expect_scope(model.nodes[2], {2, 1, 1}, {2, 1, 1});  // the push restored the scope before t()
    Eigen::Matrix3f turned;
    turned << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // a quarter turn about y, about the scope's centre
    expect_scope(model.nodes[3], {2, 1, 1}, {2, 1, 1}, turned);
}

TEST(Interpreter, ParametersConditionsAndRecursion) {
    Model model = build("A --> extrude(1) F(3)\nF(n) --> case n > 0 : F(n - 1) | else : i(box)\n", 2, 2);
    ASSERT_EQ(rules(model), (std::vector<std::string>{"A", "F", "F", "F", "F"}));
    EXPECT_EQ(tree_depth(model), 4);
    EXPECT_TRUE(model.nodes[4].has_geometry());
    EXPECT_FALSE(model.nodes[3].has_geometry());
}

TEST(Interpreter, PartsStickOutOfTheirScope) {
    Model model =
        build("W --> extrude(1) Sill\nSill --> t(-0.1, 0, 0) s(scope.sx + 0.2, 0.1, scope.sz + 0.3) i(box)\n",
              2, 1);
    const Node& sill = model.nodes[1];
    expect_scope(sill, {0, 0.5f, 0}, {1, 0.5f, 0.5f});
    Bounds bounds = node_bounds(sill);
    EXPECT_FLOAT_EQ(bounds.min.x(), -1.1f);
    EXPECT_FLOAT_EQ(bounds.max.x(), 1.1f);
    EXPECT_FLOAT_EQ(bounds.max.z(), 0.8f);
}

TEST(Interpreter, StochasticChoicesFollowTheSeed) {
    const char* text = "A --> split(x) { { 1 : B }* }\nB --> 50% : C | else : D\nC -->\nD -->\n";
    std::vector<std::string> first = rules(build(text, 40, 1, 7)), again = rules(build(text, 40, 1, 7)),
                             other = rules(build(text, 40, 1, 8));
    EXPECT_EQ(first, again);
    EXPECT_NE(first, other);
    EXPECT_NE(std::count(first.begin(), first.end(), "C"), 0);
    EXPECT_NE(std::count(first.begin(), first.end(), "D"), 0);
}

TEST(Interpreter, ProbabilitiesBelowAHundredMayChooseNothing) {
    Model model = build("A --> split(x) { { 1 : B }* }\nB --> 0% : C\nC -->\n", 5, 1);
    EXPECT_EQ(model.nodes.size(), 6u);  // A and five B, no C
}

TEST(Interpreter, MaterialsColoursAndTextures) {
    Model model = build(
        "A --> extrude(1) material(brick) i(box) [ color(\"#ff0000\") i(box) ] texture(none) i(box) "
        "material(metal) i(quad)\n",
        1, 1);
    ASSERT_EQ(model.materials.size(), 4u);
    EXPECT_EQ(model.materials[0].name, "brick");
    EXPECT_EQ(model.materials[1].name, "brick_ff0000");
    EXPECT_EQ(model.materials[2].name, "brick_none");
    EXPECT_EQ(model.materials[3].name, "metal");
    EXPECT_EQ(model.textures.size(), 2u);  // the brick colour and normal maps, once
    EXPECT_EQ(model.materials[1].base_color_texture, 0);
    EXPECT_EQ(model.materials[1].normal_texture, 1);
    EXPECT_FLOAT_EQ(model.materials[1].base_color.x(), 1);
    EXPECT_FLOAT_EQ(model.materials[1].base_color.y(), 0);
    EXPECT_EQ(model.materials[2].base_color_texture, -1);
    std::vector<int> used;
    for (const Primitive& p : model.nodes[0].primitives) used.push_back(p.material);
    EXPECT_EQ(used, (std::vector<int>{0, 1, 2, 3}));
}

TEST(Interpreter, NeighbouringPiecesContinueTheTexture) {
    Model model = build(
        "A --> extrude(2) comp(f) { front : split(x) { 1 : Q | 1 : Q } }\nQ --> material(brick) i(quad)\n", 2,
        2);
    const Primitive& left = model.nodes[1].primitives[0];
    const Primitive& right = model.nodes[2].primitives[0];
    for (std::size_t i = 0; i < left.positions.size(); ++i)
        for (std::size_t j = 0; j < right.positions.size(); ++j)
            if ((left.positions[i] - right.positions[j]).norm() < 1e-6f) {
                EXPECT_LT((left.uvs[i] - right.uvs[j]).norm(), 1e-6f);
            }
}

TEST(Interpreter, InsertsMeshAssetsFittedToTheScope) {
    auto folder = test::scratch_folder("interpreter_asset");
    test::write_text(folder / "wedge.obj",
                     "v 0 0 0\nv 2 0 0\nv 0 5 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
    test::write_text(folder / "a.grammar", "A --> extrude(3) i(\"wedge.obj\")\n");
    BuildingOptions options;
    options.lot = Eigen::Vector2f(4, 2);
    Model model = generate_building(read_grammar((folder / "a.grammar").string()), options);
    Bounds bounds = node_bounds(model.nodes[0]);
    EXPECT_LT((bounds.min - Eigen::Vector3f(-2, 0, -1)).norm(), 1e-5f);
    EXPECT_LT((bounds.max - Eigen::Vector3f(2, 3, 1)).norm(), 1e-5f);
    EXPECT_EQ(model.nodes[0].primitives[0].triangle_count(), 4u);
}

TEST(Interpreter, DefaultLotComesFromTheGrammar) {
    Grammar grammar = parse_grammar("attr lot_width = 7\nattr lot_depth = 3 + 2\nA --> NIL\n", "g.grammar");
    EXPECT_EQ(default_lot(grammar, 0), Eigen::Vector2f(7, 5));
    EXPECT_EQ(default_lot(parse_grammar("A --> NIL\n", "g.grammar"), 0), Eigen::Vector2f(20, 20));
    Model model = generate_building(grammar, {});
    expect_scope(model.nodes[0], {0, 0, 0}, {3.5f, 0, 2.5f});
}

TEST(Interpreter, ScopesBeyondTheWorldAreRefusedWhereTheyAreMade) {
    EXPECT_EQ(
        build_error("Lot --> extrude(1e39)\n"),
        "g.grammar:1:9: the scope leaves the world: a coordinate or size beyond 1000000 m, or not a number");
    EXPECT_EQ(
        build_error("Lot --> extrude(2) t(0, 2e6, 0)\n"),
        "g.grammar:1:20: the scope leaves the world: a coordinate or size beyond 1000000 m, or not a number");
    EXPECT_EQ(build_error("Lot --> extrude(1)\n", 2e6f, 1)
                  .find("the lot's width and depth must be in (0, 1000000] m"),
              11u);
}

TEST(Interpreter, StartSymbol) {
    Model model = build("A --> B\nB --> extrude(1) i(box)\n", 1, 1, 0, "B");
    EXPECT_EQ(rules(model), (std::vector<std::string>{"B"}));
}

TEST(Interpreter, Errors) {
    EXPECT_EQ(build_error("A --> B\nB --> A\n"),
              "g.grammar:1:7: rule 'B' nested deeper than 100 levels (recursion that never ends?)");
    EXPECT_EQ(build_error("A --> split(x) { { 0.01 : B }* }\nB -->\n", 100, 1, {100, 1000}),
              "g.grammar:1:27: the derivation makes more than 1000 nodes (recursion that never ends?)");
    // Pieces that make no node (NIL) still take time: splits nested inline multiply them (2M x 2M before).
    EXPECT_EQ(
        build_error("A --> extrude(1) split(x) { { 0.5 : split(z) { { 0.5 : NIL }* } }* }\n", 100, 100,
                    {100, 1000, 5000}),
        "g.grammar:1:37: the derivation makes more than 5000 split pieces and components (splits nested "
        "too finely?)");
    EXPECT_EQ(build_error("A --> extrude(1) split(x) { { 0.5 : split(z) { { 0.5 : NIL }* } }* }\n", 100, 100,
                          {100, 1000, 40200}),
              "");
    EXPECT_EQ(build_error("A --> split(x) { 3 : B | 3 : B }\nB -->\n", 5),
              "g.grammar:1:7: split(x) in rule 'A' needs 6 m but the scope is 5 m along x");
    EXPECT_EQ(build_error("A --> extrude(1) i(\"nope.obj\")\n").substr(0, 46),
              "g.grammar:1:18: cannot load asset 'nope.obj': ");
    EXPECT_EQ(
        build_error("A --> extrude(1) extrude(2)\n"),
        "g.grammar:1:18: extrude() needs a flat scope; name the axis for a solid one, e.g. extrude(y, 3)");
    EXPECT_EQ(build_error("A --> extrude(-1)\n"), "g.grammar:1:7: extrude() needs a height of at least 0");
    EXPECT_EQ(build_error("A --> s(-1, 1, 1)\n"), "g.grammar:1:7: s() cannot make a negative size");
    EXPECT_EQ(build_error("A --> extrude(1) i(cylinder, 2)\n"),
              "g.grammar:1:18: a cylinder needs 3 to 256 segments");
    EXPECT_THROW(build("A --> NIL\n", 1, 1, 0, "Z"), InputError);
    EXPECT_THROW(build("A --> NIL\n", 0, 1), InputError);
    // Was clamped to [0, 1] without a word.
    EXPECT_NE(build_error("A --> color(2, 0, 0) i(box)\n")
                  .find("g.grammar:1:7: color: 2 is not an sRGB value in [0, 1]"),
              std::string::npos)
        << build_error("A --> color(2, 0, 0) i(box)\n");
}

// Six lines of grammar asked for ten million triangles in 2.3 GB under --max-memory 0.1 (a hostile-input
// run): the model is charged against the budget as the derivation makes it.
TEST(Interpreter, ADerivationBeyondTheMemoryBudgetIsRefusedAsItGrows) {
    test::MemoryBudgetScope restore;
    const std::string fan =
        "Lot --> extrude(3) A\nA --> B B B B B B B B B B\nB --> C C C C C C C C C C\nC --> i(cylinder, "
        "256)\n";
    set_memory_budget(5e6);
    EXPECT_NE(build_error(fan).find("g.grammar: the derivation's model would need"), std::string::npos)
        << build_error(fan);
    set_memory_budget(100e6);
    EXPECT_EQ(build_error(fan), "");
}

}  // namespace boxlod
