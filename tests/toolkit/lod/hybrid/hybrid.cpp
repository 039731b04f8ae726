#include "toolkit/lod/hybrid/hybrid.h"

#include "test_support.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/cut/kept_subtrees.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/lod_builder.h"
#include "toolkit/lod/pages/bake.h"
#include "toolkit/lod/pages/boxes.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/statistics.h"
#include "toolkit/model/vertex_layout.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iterator>
#include <map>

using namespace boxlod;

namespace {

void add_quad(Primitive& p, const Eigen::Vector3f& corner, const Eigen::Vector3f& right,
              const Eigen::Vector3f& up) {
    const auto base = std::uint32_t(p.positions.size());
    const Eigen::Vector3f normal = right.cross(up).normalized();
    for (const Eigen::Vector3f& v : {corner, Eigen::Vector3f(corner + right),
                                     Eigen::Vector3f(corner + right + up), Eigen::Vector3f(corner + up)}) {
        p.positions.push_back(v);
        p.normals.push_back(normal);
    }
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    ++p.polygon_count;
}

// A flat, detailed facade: n x n tiles in four colours, flush in the plane
// z = 0, under node `facade`. A box's front face shows it exactly; simplifying
// its thousands of separate quads loses tiles.
int add_facade(Model& model, int parent, float x0, int n = 96) {
    const int first_material = int(model.materials.size());
    const Eigen::Vector4f colors[4] = {
        {0.8f, 0.2f, 0.1f, 1}, {0.1f, 0.6f, 0.2f, 1}, {0.1f, 0.2f, 0.8f, 1}, {0.9f, 0.9f, 0.2f, 1}};
    for (const Eigen::Vector4f& color : colors) model.materials.emplace_back().base_color = color;
    const int facade = add_node(model, parent, "facade");
    // n = 96: its mesh, even welded, costs more than its box's pages
    const float tile = 4.0f / n;
    for (int k = 0; k < 4; ++k)
        model.nodes[std::size_t(facade)].primitives.emplace_back().material = first_material + k;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            add_quad(model.nodes[std::size_t(facade)].primitives[std::size_t((x * 7 + y * 3) % 4)],
                     {x0 + float(x) * tile, float(y) * tile, 0}, {tile, 0, 0}, {0, tile, 0});
    return facade;
}

// A curved part: a sphere of radius 1.5 centred at (cx, 2, 0), 64 x 32 segments.
int add_sphere(Model& model, int parent, float cx) {
    model.materials.emplace_back().base_color = {0.7f, 0.7f, 0.7f, 1};
    const int sphere = add_node(model, parent, "sphere");
    Primitive& p = model.nodes[std::size_t(sphere)].primitives.emplace_back();
    p.material = int(model.materials.size()) - 1;
    const int slices = 64, stacks = 32;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j <= slices; ++j) {
            const double theta = pi * i / stacks, phi = 2 * pi * j / slices;
            const Eigen::Vector3f n(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                    float(std::sin(theta) * std::sin(phi)));
            p.positions.push_back(Eigen::Vector3f(cx, 2, 0) + 1.5f * n);
            p.normals.push_back(n);
        }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const auto a = std::uint32_t(i * (slices + 1) + j), b = a + std::uint32_t(slices + 1);
            p.indices.insert(p.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
            p.polygon_count += 2;
        }
    return sphere;
}

// A curved roof: half a cylinder of radius 2 and length 6 along z, of 96 x 24
// separate tiles in a red and white checker (as a roof's tiles are modelled).
int add_roof(Model& model, int parent) {
    const int first_material = int(model.materials.size());
    model.materials.emplace_back().base_color = {0.8f, 0.15f, 0.1f, 1};
    model.materials.emplace_back().base_color = {0.9f, 0.9f, 0.9f, 1};
    const int roof = add_node(model, parent, "roof");
    for (int k = 0; k < 2; ++k)
        model.nodes[std::size_t(roof)].primitives.emplace_back().material = first_material + k;
    const int around = 96, along = 24;
    const double pi = 3.14159265358979323846;
    auto point = [&](int i, int j) {
        const double angle = pi * i / around;
        return Eigen::Vector3f(float(2 * std::cos(angle)), float(2 * std::sin(angle)),
                               6.0f * float(j) / float(along));
    };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < along; ++j) {
            const Eigen::Vector3f corner = point(i + 1, j);
            add_quad(model.nodes[std::size_t(roof)].primitives[std::size_t((i + j) % 2)], corner,
                     point(i + 1, j + 1) - corner, point(i, j) - corner);
        }
    return roof;
}

struct Scene {
    Model model;
    int facade = -1, sphere = -1;
    std::vector<std::optional<OrientedBox>> boxes;
};

Scene facade_and_sphere() {
    Scene s;
    s.model.source = "hybrid-test";
    add_node(s.model, -1, "root");
    s.facade = add_facade(s.model, 0, -6);
    s.sphere = add_sphere(s.model, 0, 4);
    validate_model(s.model);
    s.boxes = node_boxes(s.model, BoxKind::minimal, 1);
    return s;
}

HybridSettings settings_for(float pixel_metres, int threads) {
    HybridSettings settings;
    settings.sizing.fovy_degrees = 45;
    settings.sizing.resolution = 1080;
    settings.sizing.distance =
        float(pixel_metres * 1080 / (2 * std::tan(22.5 * 3.14159265358979323846 / 180)));
    settings.threads = threads;
    return settings;
}

}  // namespace

TEST(Hybrid, TheBoxWinsOnAFlatDetailedFacadeAndSimplificationOnACurvedPart) {
    Scene s = facade_and_sphere();
    const HybridPlan plan = plan_hybrid(s.model, decode_textures(s.model), s.boxes, settings_for(0.02f, 2));
    const std::vector<Proxy>& facade = plan.proxies[std::size_t(s.facade)];
    const std::vector<Proxy>& sphere = plan.proxies[std::size_t(s.sphere)];
    ASSERT_FALSE(facade.empty());
    ASSERT_FALSE(sphere.empty());
    // The facade's box with the sizing's texels is kept, no cheaper proxy beats it, and it shows the facade
    // nearly exactly.
    auto box = std::find_if(facade.begin(), facade.end(),
                            [](const Proxy& p) { return p.kind == ProxyKind::box && p.texel_scale == 1; });
    ASSERT_NE(box, facade.end());
    for (auto p = facade.begin(); p != box; ++p) EXPECT_GT(p->error, box->error);
    for (auto p = box + 1; p != facade.end(); ++p) EXPECT_GT(p->bytes, box->bytes);
    const double facade_pixels = (4.0 / 0.02) * (4.0 / 0.02);
    EXPECT_LT(box->error, 0.05 * facade_pixels);
    // The sphere's box is beaten by a cheaper simplified sphere: it is not among its proxies.
    for (const Proxy& p : sphere) EXPECT_EQ(p.kind, ProxyKind::simplified);
    // Proxies by ascending bytes, descending error.
    for (const std::vector<Proxy>* proxies : {&facade, &sphere})
        for (std::size_t k = 1; k < proxies->size(); ++k) {
            EXPECT_GT((*proxies)[k].bytes, (*proxies)[k - 1].bytes);
            EXPECT_LT((*proxies)[k].error, (*proxies)[k - 1].error);
        }
}

// Proxies are measured among their siblings: a detailed facade sealed inside a
// closed shell is never seen, so no proxy of it has any error and only the
// cheapest is kept; measured alone, its box would show the facade's tiles.
// The shares halve from the sub-tree's own triangles: without the half, a
// level within a quarter of a building's bytes had only the eighth to draw.
TEST(Hybrid, OffersTheSubtreeSimplifiedToHalfItsTrianglesAndLargeOnesFiner) {
    Scene s = facade_and_sphere();
    const HybridPlan plan = plan_hybrid(s.model, decode_textures(s.model), s.boxes, settings_for(0.005f, 2));
    const std::size_t sphere_triangles = s.model.nodes[std::size_t(s.sphere)].primitives[0].triangle_count();
    std::vector<double> shares;
    for (const Proxy& p : plan.proxies[std::size_t(s.sphere)]) {
        std::size_t triangles = 0;
        for (const Primitive& primitive : p.primitives) triangles += primitive.triangle_count();
        shares.push_back(double(triangles) / double(sphere_triangles));
    }
    EXPECT_TRUE(std::any_of(shares.begin(), shares.end(), [](double share) {
        return share > 0.4 && share < 0.6;
    })) << ::testing::PrintToString(shares);
    // Its 4,096 triangles make it large: 1/sqrt(2) of them too.
    EXPECT_TRUE(std::any_of(shares.begin(), shares.end(), [](double share) {
        return share > 0.65 && share < 0.75;
    })) << ::testing::PrintToString(shares);
}

// Vertex clustering simplifies a whole building's many separate parts
// together: on the FZK-Haus it gives the house's best proxies within a tenth
// of its bytes; small sub-trees are not clustered.
TEST(Hybrid, ClustersLargeSubtreesWhereItBeatsEdgeCollapse) {
    const Model model = load_model(test::fzk_haus_ifc);
    const std::vector<std::optional<OrientedBox>> boxes = node_boxes(model, BoxKind::expanded, 2);
    const HybridPlan plan = plan_hybrid(model, decode_textures(model), boxes, settings_for(0.1f, 2));
    const std::vector<Proxy>& house = plan.proxies[0];
    EXPECT_TRUE(std::any_of(house.begin(), house.end(), [](const Proxy& p) { return p.clustered; }));
    const std::vector<std::size_t> triangles = subtree_triangles(model);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (const Proxy& p : plan.proxies[n]) {
            if (p.clustered) {
                EXPECT_GE(triangles[n], 1000u) << model.nodes[n].name;
            }
        }
}

// The whole house goes on being simplified below the sub-trees' last
// share (1/64): within half a percent of its bytes it is drawn as one small
// mesh; without, that budget held nothing but one box of the whole.
TEST(Hybrid, TheWholeModelIsSimplifiedForTheSmallestBudgets) {
    const Model model = load_model(test::fzk_haus_ifc);
    const std::vector<std::optional<OrientedBox>> boxes = node_boxes(model, BoxKind::expanded, 2);
    const HybridPlan plan = plan_hybrid(model, decode_textures(model), boxes, settings_for(0.4f, 2));
    const double triangles = double(subtree_triangles(model)[0]);
    const HybridLevel level = hybrid_level_within(model, plan, 0.005 * double(model_cost(model).bytes()));
    const int root = level.state[0];
    ASSERT_GE(root, 0);
    const Proxy& drawn = plan.proxies[0][std::size_t(root)];
    EXPECT_EQ(drawn.kind, ProxyKind::simplified);
    std::size_t kept = 0;
    for (const Primitive& p : drawn.primitives) kept += p.triangle_count();
    EXPECT_LT(double(kept), triangles / 64);
}

namespace {

// A level of a hybrid chain at a byte budget: its bytes, its budget's and its triangles.
struct BudgetedLevel {
    double bytes = 0, budget = 0;
    std::size_t triangles = 0;
};

// The hybrid levels 1..N of the shared CityJSON house DH_01_subs (148
// triangles) at `budgets`, measured at 64 pixels; none where ../shared/models is absent.
std::vector<BudgetedLevel> small_building_levels(const std::string& budgets) {
    const std::filesystem::path path = test::shared_model("cityjson/DH_01_subs.city.json");
    if (!std::filesystem::exists(path)) return {};
    const Model model = load_model(path.string());
    LodParameters parameters;
    parameters.level_mode = LevelMode::hybrid;
    EXPECT_EQ(parse_budgets(budgets, parameters.budgets), "");
    parameters.resolution = 64;
    auto session = start_lod(model, parameters, 2);
    const double original = double(session->derived.original_cost.bytes());
    std::vector<BudgetedLevel> levels;
    for (std::size_t c = 1; c <= parameters.budgets.size(); ++c) {
        const Lod lod = build_lod(*session, int(c), 2);
        levels.push_back({double(combined_cost({&lod.cost}).bytes()),
                          budget_bytes(parameters.budgets[c - 1], original),
                          mesh_counts(lod.model).triangles});
    }
    return levels;
}

}  // namespace

// A small building's far budgets: DH_01_subs within 2 and 1 % of its bytes
// (87 and 43). Its whole model goes on to a single triangle, so a level
// fits; stopping at 4 triangles, as the sub-trees do, 120 bytes, those
// budgets were refused as below the coarsest cut.
TEST(Hybrid, ASmallBuildingsFarBudgetsFitItsWholeModelInATriangleOrTwo) {
    const std::vector<BudgetedLevel> levels = small_building_levels("0.5,0.1,0.02,0.01");
    if (levels.empty()) GTEST_SKIP() << "../shared/models/cityjson is absent";
    for (std::size_t c = 1; c <= levels.size(); ++c)
        EXPECT_LE(levels[c - 1].bytes, levels[c - 1].budget) << c;
    EXPECT_LE(levels.back().triangles, 2u);
    EXPECT_GT(levels.back().triangles, 0u);
}

// DH_01_subs's levels are its whole model simplified: by halvings, those
// within 25 and 10 % of its bytes drew the coarser share, the second at 71 %
// of its budget; at every 2^(-1/4) of its triangles, 98 and 90 %.
TEST(Hybrid, AWholeModelLevelNearlyFillsItsBudget) {
    const std::vector<BudgetedLevel> levels = small_building_levels("0.5,0.25,0.1,0.05,0.02");
    if (levels.empty()) GTEST_SKIP() << "../shared/models/cityjson is absent";
    for (std::size_t c = 2; c <= 3; ++c) {
        EXPECT_LE(levels[c - 1].bytes, levels[c - 1].budget) << c;
        EXPECT_GE(levels[c - 1].bytes, 0.875 * levels[c - 1].budget) << c;
    }
}

TEST(Hybrid, ProxiesAreMeasuredAmongTheirSiblings) {
    Model model;
    model.source = "hybrid-test";
    add_node(model, -1, "root");
    const int facade = add_facade(model, 0, -2);  // x in [-2, 2], y in [0, 4], z = 0
    model.materials.emplace_back().base_color = {0.5f, 0.5f, 0.5f, 1};
    Primitive& shell = model.nodes[std::size_t(add_node(model, 0, "shell"))].primitives.emplace_back();
    shell.material = int(model.materials.size()) - 1;
    const Eigen::Vector3f lo(-2.2f, -0.2f, -1), hi(2.2f, 4.2f, 1);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {  // each face of the box [lo, hi], facing out
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            Eigen::Vector3f corner = lo, right = Eigen::Vector3f::Zero(), up = Eigen::Vector3f::Zero();
            corner[axis] = side ? hi[axis] : lo[axis];
            right[u] = hi[u] - lo[u];
            up[v] = hi[v] - lo[v];
            if (side)
                add_quad(shell, corner, right, up);
            else
                add_quad(shell, corner + up, right, -up);
        }
    validate_model(model);
    const auto boxes = node_boxes(model, BoxKind::minimal, 1);
    const HybridPlan plan = plan_hybrid(model, decode_textures(model), boxes, settings_for(0.02f, 1));
    const std::vector<Proxy>& hidden = plan.proxies[std::size_t(facade)];
    ASSERT_EQ(hidden.size(), 1u);
    EXPECT_EQ(hidden[0].error, 0);
}

// With baked proxies too.
TEST(Hybrid, PlansTheSameForAnyThreadCount) {
    Scene s = facade_and_sphere();
    const DecodedTextures textures = decode_textures(s.model);
    for (const bool baked : {false, true}) {
        HybridSettings on_one = settings_for(0.04f, 1), on_two = settings_for(0.04f, 2);
        on_one.baked_proxies = on_two.baked_proxies = baked;
        const HybridPlan one = plan_hybrid(s.model, textures, s.boxes, on_one);
        const HybridPlan two = plan_hybrid(s.model, textures, s.boxes, on_two);
        ASSERT_EQ(one.steps.size(), two.steps.size());
        for (std::size_t k = 0; k < one.steps.size(); ++k) {
            EXPECT_EQ(one.steps[k].node, two.steps[k].node);
            EXPECT_EQ(one.steps[k].proxy, two.steps[k].proxy);
        }
        EXPECT_EQ(one.bytes, two.bytes);
        EXPECT_EQ(one.error, two.error);
    }
}

TEST(Hybrid, MeasurementsReusedAtAnotherDistancePlanAsMeasuringAgain) {
    Scene s = facade_and_sphere();
    const DecodedTextures textures = decode_textures(s.model);
    const std::shared_ptr<HybridMeasurements> measurements = make_hybrid_measurements(s.model);
    HybridSettings near = settings_for(0.04f, 2), far = settings_for(0.11f, 2);
    near.measurements = far.measurements = measurements.get();
    plan_hybrid(s.model, textures, s.boxes, near);
    // At 11 cm the facade (5.66 m across its box: 48 measuring pixels of 11.8 cm)
    // is measured in the same view as at 4 cm and reuses its sums; the sphere
    // (5.2 m: 10.8 cm pixels at 4 cm) is measured again, in 11 cm pixels.
    const HybridPlan reused = plan_hybrid(s.model, textures, s.boxes, far);
    far.measurements = nullptr;
    const HybridPlan again = plan_hybrid(s.model, textures, s.boxes, far);
    ASSERT_EQ(reused.proxies.size(), again.proxies.size());
    for (std::size_t n = 0; n < again.proxies.size(); ++n) {
        ASSERT_EQ(reused.proxies[n].size(), again.proxies[n].size()) << n;
        for (std::size_t k = 0; k < again.proxies[n].size(); ++k) {
            EXPECT_EQ(reused.proxies[n][k].error, again.proxies[n][k].error) << n << " " << k;
            EXPECT_EQ(reused.proxies[n][k].bytes, again.proxies[n][k].bytes) << n << " " << k;
            EXPECT_EQ(reused.proxies[n][k].primitives.size(), again.proxies[n][k].primitives.size());
        }
    }
    EXPECT_EQ(reused.bytes, again.bytes);
    EXPECT_EQ(reused.error, again.error);
    // The far plan is not the near one: the reuse is not of the whole plan.
    const HybridPlan near_plan = plan_hybrid(s.model, textures, s.boxes, settings_for(0.04f, 2));
    EXPECT_NE(near_plan.bytes, again.bytes);
}

namespace {

// A root over two children a (node 1) and b (node 2) with 30 vertices each.
Model two_children() {
    Model model;
    add_node(model, -1, "root");
    for (const char* name : {"a", "b"}) {
        Primitive& p = model.nodes[std::size_t(add_node(model, 0, name))].primitives.emplace_back();
        p.positions.assign(30, Eigen::Vector3f::Zero());
        for (std::uint32_t i = 0; i < 30; ++i) p.indices.push_back(i);
    }
    return model;
}

// Hand-set proxies where the best order is known: the root's proxy is cheap and
// bad; opening it shows child a at a bad proxy and child b at a fair one; a's
// better proxy buys the most error per byte, then b's, then opening b, then a.
HybridPlan hand_set_plan(const Model& model) {
    HybridPlan plan;
    plan.proxies.resize(3);
    auto proxy = [](double bytes, double error) {
        Proxy p;
        p.bytes = bytes;
        p.error = error;
        return p;
    };
    plan.proxies[0] = {proxy(100, 1000)};
    plan.proxies[1] = {proxy(50, 400), proxy(150, 100)};  // a: +100 bytes: -300 error (3 per byte)
    plan.proxies[2] = {proxy(60, 200), proxy(100, 120)};  // b: +40 bytes: -80 error (2 per byte)
    order_hybrid_plan(model, plan);
    return plan;
}

}  // namespace

TEST(Hybrid, TakesTheLargestErrorDropPerByteFirst) {
    const Model model = two_children();
    const int a = 1, b = 2;
    const double own = double(primitive_mesh_bytes(model.nodes[std::size_t(a)].primitives[0], model));
    ASSERT_GT(own, 300);
    const HybridPlan plan = hand_set_plan(model);
    // Opening the root: 1000 -> 600 for +10 bytes (40 per byte; the root has no geometry of its own).
    const std::vector<std::pair<int, int>> expected = {{0, -1}, {a, 1}, {b, 1}, {b, -1}, {a, -1}};
    ASSERT_EQ(plan.steps.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(plan.steps[k].node, expected[k].first) << "step " << k;
        EXPECT_EQ(plan.steps[k].proxy, expected[k].second) << "step " << k;
    }
    const std::vector<double> bytes = {100, 110, 210, 250, 150 + own, 2 * own},
                              error = {1000, 600, 300, 220, 100, 0};
    EXPECT_EQ(plan.bytes, bytes);
    EXPECT_EQ(plan.error, error);
}

// The same hand-set proxies within 160 bytes: the plan's next change (a's
// better proxy, +100) does not fit after opening the root (110 bytes), so the
// level takes b's (+40) instead of stopping at 110.
TEST(Hybrid, ALevelFillsItsBudgetWithTheChangesThatFit) {
    Model model = two_children();
    HybridPlan plan = hand_set_plan(model);
    EXPECT_EQ(best_prefix_within(plan.bytes, plan.error, 160),
              1u);  // the plan's own prefix stops at 110 bytes
    const HybridLevel level = hybrid_level_within(model, plan, 160);
    EXPECT_EQ(level.bytes, 150);
    EXPECT_EQ(level.error, 520);
    EXPECT_EQ(level.state, (std::vector<int>{-1, 0, 1}));
    EXPECT_EQ(hybrid_level_within(model, plan, 50).state,
              (std::vector<int>{0, 0, 0}));  // nothing fits: the root's cheapest
}

// Both children sample one texture: the plan pays for it once, when the first
// of them keeps its geometry (paid_textures.h). The second's opening, queued
// when the texture was still to pay, is weighed again before it is taken.
TEST(Hybrid, PaysForATextureOnceHoweverManyPartsSampleIt) {
    Model model = two_children();
    model.textures.push_back({"bricks", Image8(64, 64, 3, 90)});
    model.materials.emplace_back().base_color_texture = 0;
    for (int child : {1, 2}) {
        Primitive& p = model.nodes[std::size_t(child)].primitives[0];
        p.material = 0;
        p.uvs.assign(p.positions.size(), Eigen::Vector2f::Zero());
    }
    const double own = double(primitive_mesh_bytes(model.nodes[1].primitives[0], model));
    const double texture = double(block_compressed_bytes(64, 64, GpuFormat::bc1));
    HybridPlan plan;
    plan.proxies.resize(3);
    for (auto [n, bytes, error] : {std::tuple{0, 100.0, 1000.0}, {1, 50.0, 400.0}, {2, 60.0, 200.0}}) {
        plan.proxies[std::size_t(n)].emplace_back();
        plan.proxies[std::size_t(n)][0].bytes = bytes;
        plan.proxies[std::size_t(n)][0].error = error;
    }
    order_hybrid_plan(model, plan);
    ASSERT_EQ(plan.steps.size(), 3u);
    EXPECT_EQ(plan.steps[1].node, 1);  // a: 400 error for its geometry and the texture
    const std::vector<double> bytes = {100, 110, 110 - 50 + own + texture,
                                       110 - 50 + own + texture - 60 + own};
    EXPECT_EQ(plan.bytes, bytes);
    EXPECT_EQ(plan.bytes.back(), double(model_cost(model).bytes()));  // the original, as cost.h counts it
}

// Every level within its budget, real bytes (mesh + every texture), stated in
// its statistics; a tight budget below what the estimates allow is met by stepping back.
TEST(Hybrid, LevelsByByteBudgetNeverExceedThem) {
    Scene s = facade_and_sphere();
    for (LevelMode mode : {LevelMode::hybrid, LevelMode::error_greedy}) {
        LodParameters parameters;
        parameters.level_mode = mode;
        parameters.box_kind = BoxKind::minimal;
        ASSERT_EQ(parse_budgets("0.6,0.3,0.1,0.03", parameters.budgets), "");
        parameters.distance = settings_for(0.16f, 1).sizing.distance;
        parameters.min_texture_size = 16;
        auto session = start_lod(s.model, parameters, 2);
        ASSERT_EQ(session->derived.levels.obtained_levels, 4);
        const double original = double(session->derived.original_cost.bytes());
        for (int c = 1; c <= 4; ++c) {
            Lod lod = build_lod(*session, c, 2);
            const double spent = double(combined_cost({&lod.cost}).bytes());
            const double budget = budget_bytes(parameters.budgets[std::size_t(c - 1)], original);
            EXPECT_LE(spent, budget) << level_mode_name(mode) << " level " << c;
            EXPECT_EQ(value_of(lod.statistics, "budget_bytes"), format_number(std::floor(budget)));
            EXPECT_EQ(value_of(lod.statistics, "bytes_lod"), format_number(spent));
            if (mode == LevelMode::hybrid) {  // its proxies' measured errors, stated
                EXPECT_EQ(value_of(lod.statistics, "measured_error"),
                          format_number(hybrid_cut_error(*session->derived.hybrid, lod.cut)));
            }
        }
    }
}

// Six small facades whose boxes' faces are at most 8 texels at this sizing:
// drawn flat, from one swatch, they cost far less than the pages their
// estimates count. A level that spends less than 95 % of its budget asks for
// one within a larger estimate and keeps it if it fits and errs less
// (lod_builder.cpp: grow_to_budget): without, levels 2, 3 and 4 stopped where
// their estimates did, at 3.2, 2.5 and 6.7 times the error; level 4's larger
// estimates gave the same pruned cut twice before a larger one that fits.
TEST(Hybrid, ALevelTheEstimatesUnderspendGrowsIntoItsBudget) {
    Model model;
    model.source = "flat-facades";
    add_node(model, -1, "root");
    for (int k = 0; k < 6; ++k) add_facade(model, 0, 5.0f * float(k), 8);
    validate_model(model);
    LodParameters parameters;
    parameters.level_mode = LevelMode::hybrid;
    parameters.box_kind = BoxKind::minimal;
    parameters.baked_proxies = false;  // boxes and simplified facades, whose estimates underspend
    ASSERT_EQ(parse_budgets("0.5,0.25,0.1,0.05", parameters.budgets), "");
    parameters.distance = settings_for(0.25f, 1).sizing.distance;
    auto session = start_lod(model, parameters, 2);
    const double original = double(session->derived.original_cost.bytes());
    for (int c = 1; c <= 4; ++c) {
        const double budget = budget_bytes(parameters.budgets[std::size_t(c - 1)], original);
        const HybridLevel within_estimate = hybrid_level_within(model, *session->derived.hybrid, budget);
        const Lod lod = build_lod(*session, c, 2);
        EXPECT_LE(double(combined_cost({&lod.cost}).bytes()), budget) << "level " << c;
        EXPECT_LE(lod.measured_error, within_estimate.error) << "level " << c;
        if (c >= 2) {
            EXPECT_LT(lod.measured_error * 2, within_estimate.error) << "level " << c;
        }
        const Cut kept =
            hybrid_cut(model, *session->derived.hybrid, session->cache.hybrid_levels[std::size_t(c)].state);
        EXPECT_EQ(kept.box_nodes, lod.cut.box_nodes);  // the session keeps the level drawn
        EXPECT_EQ(kept.geometry_nodes, lod.cut.geometry_nodes);
    }
}

// A textured part under untextured levels: the plan still measures it (it
// read textures never decoded: a crash in build --render-mode untextured and sweeps).
TEST(Hybrid, PlansTexturedPartsForUntexturedLevels) {
    Scene s = facade_and_sphere();
    s.model.textures.push_back({"checker", Image8(2, 2, 3, 200)});
    Primitive& sphere = s.model.nodes[std::size_t(s.sphere)].primitives[0];
    s.model.materials[std::size_t(sphere.material)].base_color_texture = 0;
    for (const Eigen::Vector3f& v : sphere.positions) sphere.uvs.push_back({v.x(), v.y()});
    validate_model(s.model);
    LodParameters parameters;
    parameters.level_mode = LevelMode::hybrid;
    parameters.render_mode = RenderMode::untextured;
    parameters.box_kind = BoxKind::minimal;
    parameters.distance = settings_for(0.04f, 1).sizing.distance;
    auto session = start_lod(s.model, parameters, 2);
    ASSERT_TRUE(session->derived.hybrid);
    EXPECT_GT(build_lod(*session, session->derived.levels.obtained_levels, 2).measured_error, 0);
}

TEST(Hybrid, LevelsDrawBoxesAndSimplifiedSubtreesWithinTheirBudgets) {
    Scene s = facade_and_sphere();
    LodParameters parameters;
    parameters.level_mode = LevelMode::hybrid;
    parameters.wanted_levels = 6;
    parameters.box_kind = BoxKind::minimal;
    parameters.min_texture_size = 16;
    parameters.distance = settings_for(0.04f, 1).sizing.distance;
    auto session = start_lod(s.model, parameters, 2);
    ASSERT_TRUE(session->derived.hybrid);
    bool some_box = false, some_simplified = false;
    for (int c = 1; c <= 6; ++c) {
        Lod lod = build_lod(*session, c, 2);
        some_box |= !lod.cut.box_nodes.empty();
        some_simplified |= !lod.cut.simplified_nodes.empty();
        // A simplified node draws no more triangles than its sub-tree, in fewer bytes (at share 1 only
        // welded).
        for (auto [node, proxy] : lod.cut.simplified_nodes) {
            const Proxy& drawn = session->derived.hybrid->proxies[std::size_t(node)][std::size_t(proxy)];
            std::size_t triangles = 0;
            for (const Primitive& p : drawn.primitives) triangles += p.triangle_count();
            EXPECT_LE(triangles, subtree_faces(s.model)[std::size_t(node)]);
            EXPECT_LT(drawn.bytes, double(subtree_mesh_bytes(s.model)[std::size_t(node)]));
        }
    }
    EXPECT_TRUE(some_box);
    EXPECT_TRUE(some_simplified);
    const Lod original = build_lod(*session, 0, 2);
    EXPECT_EQ(original.cut.box_nodes.size(), 0u);  // level 0: the original, nothing measured against it
    EXPECT_EQ(original.measured_error, 0);
    EXPECT_GT(build_lod(*session, 6, 2).measured_error, 0);
}

// A box is also offered with texels 2 to 16 times as large as the sizing's,
// each cheaper and worse than the finer, and by at least a quarter of its
// bytes: where pages are dear, a level draws several blurred boxes rather
// than one sharp one (docs/design.md: The hybrid level mode). A level drawing
// a coarse box bakes and packs it at its scale.
TEST(Hybrid, OffersTheBoxWithCoarserTexelsForFewerBytes) {
    Model model;
    model.source = "hybrid-test";
    add_node(model, -1, "root");
    const int facade = add_facade(model, 0, -2, 16);  // 4 m wide, tiles of 0.25 m
    validate_model(model);
    const auto boxes = node_boxes(model, BoxKind::minimal, 1);
    const HybridSettings settings = settings_for(0.1f, 1);
    const HybridPlan plan = plan_hybrid(model, decode_textures(model), boxes, settings);
    std::map<int, const Proxy*> by_scale;
    for (const Proxy& p : plan.proxies[std::size_t(facade)])
        if (p.kind == ProxyKind::box) by_scale[p.texel_scale] = &p;
    ASSERT_TRUE(by_scale.count(1) && by_scale.count(2) && by_scale.count(4));
    for (auto finer = by_scale.begin(), coarser = std::next(finer); coarser != by_scale.end();
         ++finer, ++coarser) {
        EXPECT_EQ(coarser->second->bytes,
                  double(box_bytes_estimate(*boxes[std::size_t(facade)],
                                            coarser_sizing(settings.sizing, double(coarser->first)), true)));
        EXPECT_LE(coarser->second->bytes, 0.75 * finer->second->bytes);
        EXPECT_GT(coarser->second->error, finer->second->error);
    }
    // At 16, pages at their least size save less than a quarter of the box at 8: not offered.
    ASSERT_TRUE(by_scale.count(8));
    EXPECT_FALSE(by_scale.count(16));
    EXPECT_GT(
        double(box_bytes_estimate(*boxes[std::size_t(facade)], coarser_sizing(settings.sizing, 16), true)),
        0.75 * by_scale[8]->bytes);

    // A budget below the box at 2: the best box that fits is the one at 4.
    LodParameters parameters;
    parameters.level_mode = LevelMode::hybrid;
    parameters.box_kind = BoxKind::minimal;
    parameters.distance = settings.sizing.distance;
    parameters.min_texture_size = 16;
    parameters.baked_proxies = false;  // the boxes alone
    ASSERT_EQ(parse_budgets(std::to_string(int(by_scale[2]->bytes)) + "B", parameters.budgets), "");
    auto session = start_lod(model, parameters, 2);
    const Lod lod = build_lod(*session, 1, 2);
    ASSERT_EQ(lod.cut.box_nodes.size(), 1u);
    const int n = lod.cut.box_nodes[0];
    ASSERT_EQ(texel_scale(lod.cut, n), 4);
    std::uint64_t texels = 0;  // the faces whole at scale 4: cropping keeps no more
    for (const OrientedBoxFace& face : oriented_box_faces(*boxes[std::size_t(n)])) {
        const Eigen::Vector2i size =
            face_texels(2 * face.half_width, 2 * face.half_height, coarser_sizing(settings.sizing, 4));
        texels += std::uint64_t(size.x()) * std::uint64_t(size.y());
    }
    EXPECT_GT(lod.face_texels, 0u);
    EXPECT_LE(lod.face_texels, texels);
}

// A curved roof of many small tiles seen from far: its box misses the curve,
// and simplified in its materials it keeps one colour or the other where
// the tiles average to pink. Offered (baked_proxies), the baked proxy has
// the curve from the roof's geometry simplified as one mesh and the tiles'
// colours from its box's faces: the roof's proxies are all simplified or
// baked, each baked one beats every simplified proxy that costs as much, and
// the budget of the cheapest baked one draws it. Not offered, none is there.
TEST(Hybrid, AFarCurvedRoofIsDrawnByItsBakedProxyWhereOffered) {
    Model model;
    model.source = "roof";
    add_node(model, -1, "root");
    const int roof = add_roof(model, 0);
    validate_model(model);
    const std::vector<std::optional<OrientedBox>> boxes = node_boxes(model, BoxKind::minimal, 1);
    HybridSettings settings = settings_for(0.1f, 2);
    const HybridPlan plain = plan_hybrid(model, decode_textures(model), boxes, settings);
    for (const Proxy& p : plain.proxies[std::size_t(roof)]) EXPECT_NE(p.kind, ProxyKind::baked);
    settings.baked_proxies = true;
    const HybridPlan plan = plan_hybrid(model, decode_textures(model), boxes, settings);
    const std::vector<Proxy>& proxies = plan.proxies[std::size_t(roof)];
    auto baked = std::find_if(proxies.begin(), proxies.end(),
                              [](const Proxy& p) { return p.kind == ProxyKind::baked; });
    ASSERT_NE(baked, proxies.end());
    for (const Proxy& p : proxies) {
        EXPECT_NE(p.kind, ProxyKind::box);
        if (p.kind == ProxyKind::simplified && p.bytes <= baked->bytes) {
            EXPECT_GT(p.error, baked->error);
        }
        if (p.kind == ProxyKind::baked) {  // baked at the box's texel scales 1, 4 and 16 only
            EXPECT_TRUE(p.texel_scale == 1 || p.texel_scale == 4 || p.texel_scale == 16) << p.texel_scale;
        }
    }
    const HybridLevel level = hybrid_level_within(model, plan, baked->bytes);
    EXPECT_EQ(level.state[std::size_t(roof)], int(baked - proxies.begin()));
    // Drawn, it samples the roof's pages: its triangles are on the level's baked page material.
    LodParameters parameters;
    parameters.level_mode = LevelMode::hybrid;
    parameters.box_kind = BoxKind::minimal;
    parameters.baked_proxies = true;
    parameters.distance = settings.sizing.distance;
    parameters.resolution = settings.sizing.resolution;
    parameters.fovy = settings.sizing.fovy_degrees;
    ASSERT_EQ(parse_budgets(std::to_string(baked->bytes * 1.5) + "B", parameters.budgets), "");
    auto session = start_lod(model, parameters, 2);
    const Lod lod = build_lod(*session, 1, 2);
    ASSERT_EQ(lod.cut.baked_nodes.size(), 1u);
    EXPECT_EQ(value_of(lod.statistics, "nodes_baked"), "1");
    bool sampled = false;
    for (const Node& node : lod.model.nodes)
        for (const Primitive& p : node.primitives)
            sampled = sampled || (lod.model.materials[std::size_t(p.material)].name.find("_proxy") !=
                                      std::string::npos &&
                                  !p.uvs.empty());
    EXPECT_TRUE(sampled);
}
