#include "toolkit/lod/hybrid/hybrid_order.h"

#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/hybrid/hybrid.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

Proxy proxy(double bytes, double error) {
    Proxy p;
    p.bytes = bytes;
    p.error = error;
    return p;
}

// A quad of geometry, far dearer than any proxy below.
void add_geometry(Model& model, int node) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    p.normals.assign(4, Eigen::Vector3f::UnitZ());
    p.indices = {0, 1, 2, 0, 2, 3};
    p.polygon_count = 1;
    model.nodes[std::size_t(node)].primitives.push_back(p);
}

// A root over two parts, each piece of geometry dearer than the budgets asked. X's box (10 bytes, error 100)
// is better than its two pieces at their cheapest (5 bytes, 60 each), but the pieces' best (10 bytes, error 0
// each) beats it: opening X gains nothing until they change. Y's better box gains 20 for 20 bytes. Within 40
// bytes the greedy order spends them on Y before it opens X; the best is X opened, its pieces at their best,
// and Y's cheap box: 30 bytes, error 100.
struct OpeningThatPaysLater {
    Model model;
    std::vector<std::vector<Proxy>> proxies;
    int x = 0, y = 0;
    OpeningThatPaysLater() {
        add_node(model, -1, "root");
        x = add_node(model, 0, "X");
        y = add_node(model, 0, "Y");
        add_geometry(model, y);
        add_geometry(model, add_node(model, x, "piece"));
        add_geometry(model, add_node(model, x, "piece"));
        proxies = {{proxy(1, 1000)},
                   {proxy(10, 100)},
                   {proxy(10, 100), proxy(30, 80)},
                   {proxy(5, 60), proxy(10, 0)},
                   {proxy(5, 60), proxy(10, 0)}};
    }
};

}  // namespace

TEST(HybridOrder, TheGreedyOrderSpendsTheBudgetBeforeAnOpeningThatPaysLater) {
    const OpeningThatPaysLater scene;
    std::vector<HybridStep> steps;
    std::vector<double> bytes, error;
    order_within(scene.model, scene.proxies, plan_prices(scene.model, scene.proxies), 40, steps, bytes,
                 error);
    const std::size_t best = best_prefix_within(bytes, error, 40);
    EXPECT_EQ(bytes[best], 40);
    EXPECT_EQ(error[best], 180);  // Y's better box and X's
}

TEST(HybridOrder, ThePrunedCutOpensWhatPaysLater) {
    const OpeningThatPaysLater scene;
    const PlanPrices prices = plan_prices(scene.model, scene.proxies);
    const std::vector<int> state = pruned_state_within(scene.model, scene.proxies, prices, 40);
    EXPECT_EQ(state, (std::vector<int>{-1, -1, 0, 1, 1}));
    // Unbounded: every part at its best (Y's geometry, the pieces' boxes of error 0, cheaper than theirs).
    EXPECT_EQ(pruned_state_within(scene.model, scene.proxies, prices, 1e9),
              (std::vector<int>{-1, -1, -1, 1, 1}));
    // Below the root's cheapest proxy nothing fits: the cheapest.
    EXPECT_EQ(pruned_state_within(scene.model, scene.proxies, prices, 0)[0], 0);
}

TEST(HybridOrder, StartingFromACutTakesItsStepsThenGoesOnGreedily) {
    const OpeningThatPaysLater scene;
    const std::vector<int> start{-1, -1, 0, 1, 1};
    std::vector<HybridStep> steps;
    std::vector<double> bytes, error;
    order_within(scene.model, scene.proxies, plan_prices(scene.model, scene.proxies), 60, steps, bytes, error,
                 &start);
    ASSERT_EQ(steps.size(), 5u);
    EXPECT_EQ(steps[0].node, 0);  // parents before their children
    EXPECT_EQ(steps[1].node, scene.x);
    EXPECT_EQ(bytes[4], 30);
    EXPECT_EQ(error[4], 100);
    EXPECT_EQ(bytes.back(), 50);  // then Y's better box
    EXPECT_EQ(error.back(), 80);
}

TEST(HybridOrder, ALevelIsTheBetterOfTheGreedyOrderAndThePrunedCut) {
    OpeningThatPaysLater scene;
    HybridPlan plan;
    plan.proxies = scene.proxies;
    order_hybrid_plan(scene.model, plan);
    const HybridLevel level = hybrid_level_within(scene.model, plan, 40);
    EXPECT_EQ(level.bytes, 30);
    EXPECT_EQ(level.error, 100);
    EXPECT_EQ(level.state, (std::vector<int>{-1, -1, 0, 1, 1}));
}

// A budget below the root's cheapest proxy (30 bytes), met only two openings
// down (its pieces at 5 bytes each): the greedy order cannot take the first
// opening (it saves 2 bytes, still 28 over), the pruned cut takes both. The
// level within the budget wins, whatever its error.
TEST(HybridOrder, ALevelWithinTheBudgetBeatsADearerStart) {
    Model model;
    add_node(model, -1, "root");
    const int x = add_node(model, 0, "X");
    add_geometry(model, add_node(model, x, "piece"));
    add_geometry(model, add_node(model, x, "piece"));
    HybridPlan plan;
    plan.proxies = {{proxy(30, 5)}, {proxy(28, 50)}, {proxy(5, 100)}, {proxy(5, 100)}};
    order_hybrid_plan(model, plan);
    const HybridLevel level = hybrid_level_within(model, plan, 20);
    EXPECT_EQ(level.bytes, 10);
    EXPECT_EQ(level.error, 200);
    EXPECT_EQ(level.state, (std::vector<int>{-1, -1, 0, 0}));
}
