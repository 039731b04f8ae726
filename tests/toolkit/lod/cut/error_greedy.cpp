#include "toolkit/lod/cut/error_greedy.h"
#include "toolkit/lod/cut/level_values.h"

#include "toolkit/lod/cut/cut.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {

// A square (two triangles) of side `side` in the plane z, centred on (x, 0.5).
Primitive square(float x, float z, float side) {
    Primitive p;
    float h = side / 2;
    p.positions = {{x - h, 0.5f - h, z}, {x + h, 0.5f - h, z}, {x + h, 0.5f + h, z}, {x - h, 0.5f + h, z}};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.polygon_count = 1;
    return p;
}

OrientedBox box_around(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
    OrientedBox box;
    box.center = (lo + hi) / 2;
    box.half_extents = (hi - lo) / 2;
    return box;
}

// A root over two parts in [0, 1] x [0, 1] x [0, 1] and [2, 3] x [0, 1] x [0, 1]:
// `deep` a square recessed 0.4 behind its box's front face, `flat` one on its face.
struct TwoParts {
    Model model;
    std::vector<std::optional<OrientedBox>> boxes;
    int deep, flat;
};

TwoParts two_parts() {
    TwoParts t;
    add_node(t.model, -1, "root");
    t.deep = add_node(t.model, 0, "deep");
    t.flat = add_node(t.model, 0, "flat");
    t.model.nodes[std::size_t(t.deep)].primitives.push_back(square(0.5f, 0.6f, 0.5f));  // 0.4 behind z = 1
    t.model.nodes[std::size_t(t.flat)].primitives.push_back(square(2.5f, 1.0f, 0.5f));
    OrientedBox deep_box = box_around({0, 0, 0}, {1, 1, 1}), flat_box = box_around({2, 0, 0}, {3, 1, 1});
    t.boxes = {box_around({0, 0, 0}, {3, 1, 1}), deep_box, flat_box};
    return t;
}

}  // namespace

TEST(ErrorGreedy, BoxErrorIsAreaTimesDepthBehindTheFaces) {
    TwoParts t = two_parts();
    std::vector<double> e = box_depth_errors(t.model, t.boxes);
    EXPECT_NEAR(e[std::size_t(t.deep)], 0.25 * 0.4, 1e-6);  // area 0.25, 0.4 from the nearest face
    EXPECT_NEAR(e[std::size_t(t.flat)], 0, 1e-7);           // on its face
    EXPECT_NEAR(e[0], 0.25 * 0.4, 1e-6);                    // the root's box: the same distances
}

TEST(ErrorGreedy, OpensWhereTheErrorIsFirst) {
    TwoParts t = two_parts();
    TextureSizing sizing;
    GreedyOpening opening = greedy_opening(t.model, t.boxes, sizing, true);
    // The root first (the only node on the frontier), then the deep part, whose box hides 0.1 m^3;
    // the flat part's box loses nothing and comes last.
    EXPECT_EQ(opening.order, (std::vector<int>{0, t.deep, t.flat}));
    ASSERT_EQ(opening.bytes.size(), 4u);
    ASSERT_EQ(opening.error.size(), 4u);
    EXPECT_NEAR(opening.error[2], 0, 1e-6);  // once the deep part is open nothing is lost
    EXPECT_EQ(opening.bytes, greedy_opening(t.model, t.boxes, sizing, true).bytes);  // deterministic
}

TEST(ErrorGreedy, LevelsCutTheOpeningAtByteBudgets) {
    TwoParts t = two_parts();
    for (int wanted : {1, 2, 4, 8}) {
        LevelValues values =
            compute_level_values(t.model, LevelMode::error_greedy, wanted, Interpolation::linear, t.boxes);
        EXPECT_EQ(values.obtained_levels, wanted);
        for (std::size_t n = 1; n < t.model.nodes.size();
             ++n)  // a child is never open where its parent is boxed
            EXPECT_LE(values.level[n], values.level[std::size_t(t.model.nodes[n].parent)]) << n;
        // Level 0 is the original; the deep part is open at least wherever the flat one is.
        EXPECT_TRUE(take_cut(t.model, values.level, 0, t.boxes).box_nodes.empty());
        EXPECT_GE(values.level[std::size_t(t.deep)], values.level[std::size_t(t.flat)]);
        // Each coarser level draws fewer bytes' worth: never more boxes opened than at a finer level.
        for (int c = 1; c < wanted; ++c)
            EXPECT_GE(take_cut(t.model, values.level, c, t.boxes).used_nodes.size(),
                      take_cut(t.model, values.level, c + 1, t.boxes).used_nodes.size());
    }
}
