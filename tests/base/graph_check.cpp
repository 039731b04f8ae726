#include "base/graph_check.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

std::string problem(const std::vector<std::vector<std::uint32_t>>& edges, int max_depth) {
    return test::input_error_of([&] {
        check_acyclic_and_shallow(
            edges, [](std::uint32_t node) { return "node " + std::to_string(node); }, "links", "g.txt",
            max_depth);
    });
}

}  // namespace

TEST(GraphCheck, ACycleIsRefusedWhereItCloses) {
    EXPECT_EQ(problem({{1}, {2}, {}}, 10), "");
    EXPECT_EQ(problem({{1}, {2}, {0}}, 10), "g.txt: node 0: links form a cycle");
    EXPECT_EQ(problem({{}, {1}}, 10), "g.txt: node 1: links form a cycle");
    // Shared successors (a diamond) are no cycle.
    EXPECT_EQ(problem({{1, 2}, {3}, {3}, {}}, 10), "");
}

TEST(GraphCheck, PathsDeeperThanTheLimitAreRefused) {
    std::vector<std::vector<std::uint32_t>> chain(5);  // five nodes deep
    for (std::uint32_t n = 0; n + 1 < chain.size(); ++n) chain[n] = {n + 1};
    EXPECT_EQ(problem(chain, 5), "");
    EXPECT_NE(problem(chain, 4).find("links nested more than"), std::string::npos);
    // A deep path found from a later root, below nodes already done, counts whole.
    chain.push_back({0});
    EXPECT_NE(problem(chain, 5).find("links nested more than"), std::string::npos);
}
