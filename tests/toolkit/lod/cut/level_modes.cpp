#include "toolkit/lod/cut/level_modes.h"
#include "toolkit/lod/cut/level_values.h"

#include "base/input_error.h"
#include "test_support.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/cut/cut.h"
#include "toolkit/lod/pages/boxes.h"

#include <gtest/gtest.h>

namespace boxlod {
namespace {

// root -> a, b; a -> c -> e; b -> d. Depth 3. Indices: root 0, a 1, b 2, c 3, d 4, e 5.
Model hand_tree() {
    Model model;
    int root = add_node(model, -1, "root");
    int a = add_node(model, root, "a");
    int b = add_node(model, root, "b");
    int c = add_node(model, a, "c");
    add_node(model, b, "d");
    add_node(model, c, "e");
    return model;
}

LevelValues hierarchy_levels(const Model& model, LevelMode mode) {
    return compute_level_values(model, mode, 1, Interpolation::linear, {});
}

OrientedBox box_with_half_extents(float x, float y, float z) {
    OrientedBox box;
    box.half_extents = {x, y, z};
    return box;
}

// A root and four leaves whose boxes have half-extents (1, 1, h): volume 8h,
// area 8 + 16h, longest side 2 max(1, h).
struct BoxedModel {
    Model model;
    std::vector<std::optional<OrientedBox>> boxes;
};
BoxedModel boxed_leaves(const std::vector<float>& heights, float root_height) {
    BoxedModel out;
    int root = add_node(out.model, -1, "root");
    out.boxes.push_back(box_with_half_extents(1, 1, root_height));
    for (float h : heights) {
        add_node(out.model, root, "leaf");
        out.boxes.push_back(box_with_half_extents(1, 1, h));
    }
    return out;
}

TEST(LevelModes, NamesRoundTrip) {
    for (LevelMode mode :
         {LevelMode::top_down, LevelMode::bottom_up, LevelMode::bottom_up_siblings, LevelMode::box_volume,
          LevelMode::box_area, LevelMode::box_diagonal, LevelMode::box_max_extent}) {
        LevelMode parsed{};
        ASSERT_TRUE(parse_level_mode(level_mode_name(mode), parsed));
        EXPECT_EQ(parsed, mode);
    }
    LevelMode mode{};
    EXPECT_TRUE(parse_level_mode("bottom-up-siblings", mode));
    EXPECT_EQ(mode, LevelMode::bottom_up_siblings);
    EXPECT_FALSE(parse_level_mode("sideways", mode));
    Interpolation interpolation{};
    EXPECT_TRUE(parse_interpolation("rank", interpolation));
    EXPECT_EQ(interpolation, Interpolation::rank);
    EXPECT_STREQ(interpolation_name(Interpolation::log), "log");
    EXPECT_FALSE(parse_interpolation("cubic", interpolation));
    EXPECT_TRUE(is_box_mode(LevelMode::box_max_extent));
    EXPECT_FALSE(is_box_mode(LevelMode::bottom_up));
}

TEST(LevelModes, TopDown) {
    LevelValues values = hierarchy_levels(hand_tree(), LevelMode::top_down);
    EXPECT_EQ(values.obtained_levels, 4);
    EXPECT_EQ(values.level, (std::vector<int>{3, 2, 2, 1, 1, 0}));
}

TEST(LevelModes, BottomUp) {
    LevelValues values = hierarchy_levels(hand_tree(), LevelMode::bottom_up);
    EXPECT_EQ(values.obtained_levels, 4);
    EXPECT_EQ(values.level, (std::vector<int>{3, 2, 1, 1, 0, 0}));
}

TEST(LevelModes, BottomUpSiblingsRaisesSiblings) {
    // b (1 in bottom-up) is raised to its sibling a's 2; d stays a leaf at 0.
    LevelValues values = hierarchy_levels(hand_tree(), LevelMode::bottom_up_siblings);
    EXPECT_EQ(values.obtained_levels, 4);
    EXPECT_EQ(values.level, (std::vector<int>{3, 2, 2, 1, 0, 0}));
}

TEST(LevelModes, BottomUpSiblingsRaisesLeafSiblings) {
    // root -> x, y; x -> z. Bottom-up gives the leaf y 0, sibling-same-level 1.
    Model model;
    int root = add_node(model, -1, "root");
    int x = add_node(model, root, "x");
    add_node(model, root, "y");
    add_node(model, x, "z");
    EXPECT_EQ(hierarchy_levels(model, LevelMode::bottom_up).level, (std::vector<int>{2, 1, 0, 0}));
    EXPECT_EQ(hierarchy_levels(model, LevelMode::bottom_up_siblings).level, (std::vector<int>{2, 1, 1, 0}));
}

TEST(LevelModes, LoneRootHasOneLevel) {
    Model model;
    add_node(model, -1, "root");
    for (LevelMode mode : {LevelMode::top_down, LevelMode::bottom_up, LevelMode::bottom_up_siblings}) {
        LevelValues values = hierarchy_levels(model, mode);
        EXPECT_EQ(values.obtained_levels, 1);
        EXPECT_EQ(values.level, (std::vector<int>{0}));
    }
}

TEST(LevelModes, HierarchyModesGiveTheCutSemantics) {
    // c = 0 keeps everything (no level below 0); c = N replaces the root (its level is N - 1).
    for (LevelMode mode : {LevelMode::top_down, LevelMode::bottom_up, LevelMode::bottom_up_siblings}) {
        LevelValues values = hierarchy_levels(hand_tree(), mode);
        EXPECT_EQ(values.level[0], values.obtained_levels - 1);
        for (int level : values.level) EXPECT_GE(level, 0);
    }
}

TEST(LevelModes, CutOfTopDownAtNIsTheRootBoxAndAtZeroTheOriginal) {
    Model model = hand_tree();
    std::vector<std::optional<OrientedBox>> boxes(model.nodes.size(), box_with_half_extents(1, 1, 1));
    LevelValues values = hierarchy_levels(model, LevelMode::top_down);
    Cut top = take_cut(model, values.level, values.obtained_levels, boxes);
    EXPECT_EQ(top.box_nodes, (std::vector<int>{0}));
    EXPECT_TRUE(top.geometry_nodes.empty());
    Cut original = take_cut(model, values.level, 0, boxes);
    EXPECT_TRUE(original.box_nodes.empty());
    EXPECT_EQ(original.used_nodes.size(), model.nodes.size());
}

TEST(LevelModes, BoxVolumeLinear) {
    // Volumes 8, 16, 24, 40 (root) -> t = 0, 1/4, 1/2, 1 -> with N = 5: 0, 1, 2, 4.
    BoxedModel m = boxed_leaves({1, 2, 3}, 5);
    LevelValues values =
        compute_level_values(m.model, LevelMode::box_volume, 5, Interpolation::linear, m.boxes);
    EXPECT_EQ(values.obtained_levels, 5);
    EXPECT_EQ(values.level, (std::vector<int>{4, 0, 1, 2}));
}

TEST(LevelModes, BoxAreaAndMaxExtentLinear) {
    // Areas 8 + 16h = 24, 40, 56, 88 and longest sides 2, 4, 6, 10: both t = (h - 1) / 4.
    BoxedModel m = boxed_leaves({1, 2, 3}, 5);
    for (LevelMode mode : {LevelMode::box_area, LevelMode::box_max_extent}) {
        LevelValues values = compute_level_values(m.model, mode, 5, Interpolation::linear, m.boxes);
        EXPECT_EQ(values.level, (std::vector<int>{4, 0, 1, 2})) << level_mode_name(mode);
    }
}

TEST(LevelModes, BoxDiagonalLinear) {
    // Boxes along one axis: diagonal 2h = 2, 4, 6, 10.
    Model model;
    std::vector<std::optional<OrientedBox>> boxes;
    int root = add_node(model, -1, "root");
    boxes.push_back(box_with_half_extents(5, 0, 0));
    for (float h : {1.f, 2.f, 3.f}) {
        add_node(model, root, "leaf");
        boxes.push_back(box_with_half_extents(h, 0, 0));
    }
    LevelValues values =
        compute_level_values(model, LevelMode::box_diagonal, 5, Interpolation::linear, boxes);
    EXPECT_EQ(values.level, (std::vector<int>{4, 0, 1, 2}));
}

TEST(LevelModes, EqualValuesGiveTheTopLevel) {
    // Every area is 0 (vmin = vmax): t = 1 for every boxed node, for every interpolation.
    Model model;
    int root = add_node(model, -1, "root");
    add_node(model, root, "a");
    add_node(model, root, "unboxed");
    std::vector<std::optional<OrientedBox>> boxes{box_with_half_extents(3, 0, 0),
                                                  box_with_half_extents(1, 0, 0), std::nullopt};
    for (Interpolation interpolation : {Interpolation::linear, Interpolation::log, Interpolation::rank}) {
        LevelValues values = compute_level_values(model, LevelMode::box_area, 3, interpolation, boxes);
        EXPECT_EQ(values.level, (std::vector<int>{2, 2, 0})) << interpolation_name(interpolation);
    }
}

TEST(LevelModes, NodesWithoutBoxTakeNoPart) {
    // The unboxed node's would-be value does not stretch the range; it gets level 0.
    BoxedModel m = boxed_leaves({1, 2, 3}, 5);
    add_node(m.model, 0, "empty");
    m.boxes.push_back(std::nullopt);
    LevelValues values =
        compute_level_values(m.model, LevelMode::box_volume, 5, Interpolation::linear, m.boxes);
    EXPECT_EQ(values.level, (std::vector<int>{4, 0, 1, 2, 0}));
}

TEST(LevelModes, LogInterpolation) {
    // Volumes 8 * {64, 1, 2, 8}: log2 offsets 6, 0, 1, 3 -> t = 1, 0, 1/6, 1/2 -> N = 4: 3, 0, 0, 1.
    BoxedModel m = boxed_leaves({1, 2, 8}, 64);
    LevelValues log = compute_level_values(m.model, LevelMode::box_volume, 4, Interpolation::log, m.boxes);
    EXPECT_EQ(log.level, (std::vector<int>{3, 0, 0, 1}));
    // Linear on the same values: t = 1, 0, 8/504, 56/504 -> 3, 0, 0, 0.
    LevelValues linear =
        compute_level_values(m.model, LevelMode::box_volume, 4, Interpolation::linear, m.boxes);
    EXPECT_EQ(linear.level, (std::vector<int>{3, 0, 0, 0}));
}

TEST(LevelModes, LogOfZeroVolumeIsFloored) {
    // Volumes 512 (root), 0, 8, 64: the zero is floored, not -infinity; it sits far below the rest.
    BoxedModel m = boxed_leaves({0, 1, 8}, 64);
    LevelValues values = compute_level_values(m.model, LevelMode::box_volume, 4, Interpolation::log, m.boxes);
    EXPECT_EQ(values.level, (std::vector<int>{3, 0, 2, 2}));
}

TEST(LevelModes, RankInterpolationWithTies) {
    // Heights 5 (root), 1, 2, 2, 3: ranks 4, 0, 1, 1, 3 (ties share the lowest) -> t = rank / 4.
    BoxedModel m = boxed_leaves({1, 2, 2, 3}, 5);
    LevelValues values =
        compute_level_values(m.model, LevelMode::box_max_extent, 5, Interpolation::rank, m.boxes);
    EXPECT_EQ(values.level, (std::vector<int>{4, 0, 1, 1, 3}));
    // Linear on the same values: longest sides 2, 4, 4, 6, 10 -> t = (h - 1) / 4 -> 0, 1, 1, 2.
    LevelValues linear =
        compute_level_values(m.model, LevelMode::box_max_extent, 5, Interpolation::linear, m.boxes);
    EXPECT_EQ(linear.level, (std::vector<int>{4, 0, 1, 1, 2}));
}

TEST(LevelModes, OneWantedLevelPutsEverythingAtZero) {
    BoxedModel m = boxed_leaves({1, 2, 3}, 5);
    LevelValues values =
        compute_level_values(m.model, LevelMode::box_volume, 1, Interpolation::linear, m.boxes);
    EXPECT_EQ(values.obtained_levels, 1);
    EXPECT_EQ(values.level, (std::vector<int>{0, 0, 0, 0}));
}

TEST(LevelModes, BoxModesRejectFewerThanOneLevel) {
    BoxedModel m = boxed_leaves({1}, 2);
    EXPECT_THROW(compute_level_values(m.model, LevelMode::box_volume, 0, Interpolation::linear, m.boxes),
                 InputError);
}

TEST(LevelModes, FzkHausEveryModeAndBoxKind) {
    Model model = load_model(test::fzk_haus_ifc);
    for (BoxKind kind : {BoxKind::scope, BoxKind::expanded, BoxKind::minimal}) {
        auto boxes = node_boxes(model, kind, 0);
        for (LevelMode mode :
             {LevelMode::top_down, LevelMode::bottom_up, LevelMode::bottom_up_siblings, LevelMode::box_volume,
              LevelMode::box_area, LevelMode::box_diagonal, LevelMode::box_max_extent}) {
            for (Interpolation interpolation :
                 {Interpolation::linear, Interpolation::log, Interpolation::rank}) {
                LevelValues values = compute_level_values(model, mode, 6, interpolation, boxes);
                ASSERT_EQ(values.level.size(), model.nodes.size());
                if (is_box_mode(mode)) {
                    EXPECT_EQ(values.obtained_levels, 6);
                }
                for (int level : values.level) {
                    EXPECT_GE(level, 0);
                    EXPECT_LT(level, values.obtained_levels);
                }
                // c = N leaves the root's box alone.
                Cut top = take_cut(model, values.level, values.obtained_levels, boxes);
                EXPECT_EQ(top.box_nodes, (std::vector<int>{0})) << level_mode_name(mode);
            }
        }
    }
}

}  // namespace
}  // namespace boxlod
