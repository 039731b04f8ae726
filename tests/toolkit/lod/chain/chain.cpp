#include "toolkit/lod/chain/chain.h"

#include "base/input_error.h"
#include "base/memory_budget.h"
#include "lod_scene.h"
#include "test_support.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/parameter_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

using namespace boxlod;

namespace {

LodParameters small_chain_parameters() {
    LodParameters p;
    p.resolution = 64;
    p.min_texture_size = 16;
    p.max_texture_size = 64;
    return p;
}

LevelDistances listed(std::vector<float> distances) {
    return {LevelDistances::Rule::listed, std::move(distances)};
}

}  // namespace

TEST(Chain, AutoSizesEachLevelForTwiceTheLastDistance) {
    EXPECT_EQ(doubled_distance(10, 1), 10);
    EXPECT_EQ(doubled_distance(10, 4), 80);
    EXPECT_EQ(level_distances({}, 10, 4), (std::vector<float>{10, 20, 40, 80}));
    EXPECT_EQ(level_distances({LevelDistances::Rule::same, {}}, 10, 4), std::vector<float>{});
    EXPECT_EQ(level_distances(listed({5, 6, 9}), 10, 3), (std::vector<float>{5, 6, 9}));
    EXPECT_EQ(test::input_error_of([] {
                  level_distances(listed({5, 6}), 10, 3);
              }),
              "level_distances (--level-distances) 5,6: 2 distances for 3 levels; list 3 (levels 1..3), or "
              "auto, or same");
}

TEST(Chain, AutoSizesABudgetsLevelNoFartherThanItsShareOfTheFirst) {
    const auto fractions = [](std::vector<double> values) {
        std::vector<ByteBudget> budgets;
        for (double v : values) budgets.push_back({true, v});
        return budgets;
    };
    // Halvings and the default ladder keep the doubling; a finer ladder follows its budgets.
    EXPECT_EQ(level_distances({}, 10, 4, fractions({0.5, 0.25, 0.1, 0.05})),
              (std::vector<float>{10, 20, 40, 80}));
    EXPECT_EQ(level_distances({}, 10, 4, fractions({0.5, 0.4, 0.25, 0.2})),
              (std::vector<float>{10, 12.5, 20, 25}));
    EXPECT_EQ(level_distances({}, 10, 2, {{false, 2e6}, {false, 1e6}}), (std::vector<float>{10, 20}));
    EXPECT_EQ(level_distances({}, 10, 3, fractions({0.5, 0.4})),
              (std::vector<float>{10, 20, 40}));  // not one a level
    EXPECT_EQ(level_distances(listed({5, 6}), 10, 2, fractions({0.5, 0.49})), (std::vector<float>{5, 6}));
}

// Equal distances would size two levels alike (issue 73: accepted without a word).
TEST(Chain, ListedDistancesAscendStrictlyWithinTheirRange) {
    LodParameters p;
    const ParameterDeclaration& d = *find_lod_parameter("level_distances");
    EXPECT_EQ(d.parse("10,10,20", p), "10 comes after 10: the distances must ascend, one per level 1..N");
    EXPECT_EQ(d.parse("1,2,2e12", p), "'2e12' is not a distance in [0.001, 1e+12] m (or auto, or same)");
    EXPECT_EQ(d.parse("nan", p), "'nan' is not a distance in [0.001, 1e+12] m (or auto, or same)");
    EXPECT_EQ(d.parse("10,20,", p), "'' is not a distance in [0.001, 1e+12] m (or auto, or same)");
    EXPECT_EQ(p.level_distances.rule, LevelDistances::Rule::doubling);  // a refused value changes nothing
    EXPECT_EQ(d.parse("1.5,20,40.25", p), "");
    EXPECT_EQ(d.format(p), "1.5,20,40.25");
    EXPECT_EQ(d.parse("same", p), "");
    EXPECT_EQ(d.format(p), "same");
    LodParameters manual;
    set_manual(manual);
    EXPECT_EQ(manual.level_distances.rule, LevelDistances::Rule::same);
}

// A building in centimetres frames at some 10^4 units: its 10-level chain
// sized levels past 10^6, which their own parameters refused (exit 2 from
// `build --chain` on assimp's animation_with_skeleton.fbx, 7 km wide).
TEST(Chain, ABuildingInCentimetresBuildsItsFarLevels) {
    Model model = test::lod_test_building();
    for (Node& node : model.nodes)
        for (Primitive& primitive : node.primitives)
            for (Eigen::Vector3f& position : primitive.positions) position *= 2000;
    LodParameters p = small_chain_parameters();
    const float first = Chain(model, p, 2).parameters().distance;
    ASSERT_GT(first * 512, 1e6f);
    p.distance = first * 512;  // a 10-level chain's level 10
    Chain far(model, p, 2);
    EXPECT_EQ(far.sized_parameters(far.obtained_levels()).distance,
              first * 512 * float(std::ldexp(1.0, far.obtained_levels() - 1)));
    EXPECT_EQ(test::input_error_of([&] { far.build(far.obtained_levels()); }), "");
    // 64 levels double past any range: the farthest stay at its end, still ascending.
    const std::vector<float> many = level_distances({}, first, 64);
    EXPECT_EQ(double(many.back()), double(float(parameter_range::distance.max)));
    EXPECT_TRUE(std::is_sorted(many.begin(), many.end()));
}

// Each level is sized by the chain, whichever command asks: level c's session
// sizes for d_c; --manual's (same) for the one distance; past the levels
// obtained, build_lod refuses the level.
TEST(Chain, EachLevelIsSizedForItsOwnDistance) {
    const Model model = test::lod_test_building();
    Chain chain(model, small_chain_parameters(), 2);
    const float d = chain.parameters().distance;
    EXPECT_EQ(&chain.for_level(0), chain.first.get());
    EXPECT_EQ(&chain.for_level(1), chain.first.get());  // auto's level 1 is at the distance
    EXPECT_EQ(chain.sized_parameters(3).distance, 4 * d);
    EXPECT_EQ(chain.sized_parameters(3).level_distances.rule, LevelDistances::Rule::same);
    EXPECT_EQ(&chain.for_level(3), &chain.for_level(3));  // one session per distance
    EXPECT_NE(test::input_error_of([&] { chain.build(99); }), "");
    LodParameters manual = small_chain_parameters();
    set_manual(manual);
    manual.max_texture_size = 256;
    Chain same(model, manual, 2);
    EXPECT_TRUE(same.distances.empty());
    EXPECT_EQ(&same.for_level(same.obtained_levels()), same.first.get());
}

// What a sweep gives a chain: boxes it computed once (reused, not made
// again), and budgets that only report (a level no cut fits draws the
// coarsest, over its budget, instead of failing), at every distance.
TEST(Chain, TakesGivenBoxesAndLenientBudgetsAtEveryDistance) {
    const Model model = test::lod_test_building();
    LodParameters p = small_chain_parameters();
    p.level_mode = LevelMode::error_greedy;
    p.budgets = {ByteBudget{true, 2e-6}, ByteBudget{true, 1e-6}};
    std::vector<std::optional<OrientedBox>> boxes = node_boxes(model, p.box_kind, 2);
    ASSERT_TRUE(boxes[0]);
    boxes[0]->center.x() += 0.01f;  // a box no computation makes: seen only if the chain takes it
    Chain lenient(model, p, 2, {.boxes = &boxes, .budgets_strict = false});
    EXPECT_EQ(lenient.boxes()[0]->center, boxes[0]->center);
    Chain strict(model, p, 2);
    ASSERT_EQ(strict.obtained_levels(), 2);
    for (int c : {1, 2}) {
        EXPECT_NE(test::input_error_of([&] { strict.build(c); }), "") << "level " << c;
        const Lod lod = lenient.build(c);
        EXPECT_GT(combined_cost({&lod.cost}).bytes(), 2e-6 * double(model_cost(model).bytes()))
            << "level " << c;
    }
    EXPECT_NE(&lenient.for_level(2), lenient.first.get());  // level 2 sized by a session of its own
}

// Levels in order, each once: a level that draws what the one before draws
// is named by it (the paying chain of a small building keeps its geometry at
// every level: all are level 0), and the cap counts distinct levels.
TEST(Chain, TakesEachDistinctLevelOnceAndNamesTheRepeats) {
    const Model model = test::lod_test_building();
    LodParameters manual = small_chain_parameters();
    set_manual(manual);  // every sub-tree boxed: levels differ
    manual.max_texture_size = 256;
    for (const LodParameters& p : {small_chain_parameters(), manual}) {
        Chain chain(model, p, 2);
        const int obtained = chain.obtained_levels();
        std::vector<ChainLevel> taken;
        EXPECT_EQ(take_distinct_levels(chain, 0, obtained, 100,
                                       [&](ChainLevel level) { taken.push_back(std::move(level)); }),
                  obtained + 1);
        std::vector<int> every;  // each level once, as taken or as a repeat
        for (std::size_t i = 0; i < taken.size(); ++i) {
            every.push_back(taken[i].level);
            EXPECT_EQ(taken[i].lod.current_level, taken[i].level);
            if (i > 0) {
                EXPECT_FALSE(draws_the_same(taken[i - 1].lod.model, taken[i].lod.model))
                    << "level " << taken[i].level;
            }
            for (int c : taken[i].same_levels) {
                every.push_back(c);
                EXPECT_TRUE(draws_the_same(taken[i].lod.model, chain.build(c).model)) << "level " << c;
            }
        }
        std::sort(every.begin(), every.end());
        ASSERT_EQ(every.size(), std::size_t(obtained + 1));
        for (int c = 0; c <= obtained; ++c) EXPECT_EQ(every[std::size_t(c)], c);
        if (!p.keep_cheaper_subtrees) {
            ASSERT_GE(taken.size(), 3u);
            // At most two: the first level not held is the third distinct one.
            std::vector<int> capped;
            const int cut = take_distinct_levels(chain, 0, obtained, 2,
                                                 [&](ChainLevel level) { capped.push_back(level.level); });
            EXPECT_EQ(capped, (std::vector<int>{taken[0].level, taken[1].level}));
            EXPECT_EQ(cut, taken[2].level);
        } else {
            EXPECT_EQ(taken.size(),
                      1u);  // the paying chain of a building this small: its geometry at every level
        }
    }
}

// A chain is estimated whole: the levels a command holds and every
// distance's baked faces count against the memory budget beside the level
// being made (a chain of 8192 x 8192 pages ran out of memory at 3.9 GB while
// each level alone was within its 2 GB budget; from a hostile-input run).
TEST(Chain, LevelsHeldCountAgainstTheMemoryBudget) {
    test::MemoryBudgetScope scope;
    const Model model = test::lod_test_building();
    LodParameters manual = small_chain_parameters();
    set_manual(manual);  // every sub-tree boxed: every level has pages
    manual.max_texture_size = 256;
    const double before = held_memory();
    Chain chain(model, manual, 2);
    std::optional<Lod> first = chain.build(1);
    ASSERT_FALSE(first->atlas.pages.empty());
    const double with_first = held_memory();
    double page_texels = 0;
    for (const Eigen::Vector2i& page : first->atlas.pages) page_texels += double(page.x()) * page.y();
    EXPECT_GE(with_first - before, 9 * page_texels);  // its pages and its session's faces
    first.reset();
    EXPECT_EQ(held_memory(), with_first - 9 * page_texels);  // the faces stay for later levels
    const Lod kept = chain.build(1);
    set_memory_budget(held_memory() + 1);
    EXPECT_NE(test::input_error_of([&] { chain.build(2); }).find(" held, more than the memory budget"),
              std::string::npos);
}

// A level's parameter file holds the chain's parameters at the level's
// number: building from it makes the same level (a level is a level).
TEST(Chain, ALevelsParameterFileBuildsTheSameLevel) {
    const Model model = test::lod_test_building();
    Chain chain(model, small_chain_parameters(), 2);
    const int c = chain.obtained_levels() - 1;
    ASSERT_GE(c, 2);
    LodParameters saved = chain.parameters();
    saved.current_level = c;
    const LodParameters read = parse_parameters(format_parameters(saved), "level.params.txt");
    Chain again(model, read, 2);
    const Lod a = chain.build(c), b = again.build(read.current_level);
    EXPECT_EQ(again.sized_parameters(c).distance, chain.sized_parameters(c).distance);
    EXPECT_TRUE(draws_the_same(a.model, b.model));
    EXPECT_EQ(format_key_values(a.statistics), format_key_values(b.statistics));
}

// A chain as engines get it: levels that switch in farther and cost less,
// each within the threshold from its switch distance on; without a
// threshold, at their sizing distances.
TEST(Chain, SwitchesEachLevelWhereItsMeasuredErrorIsWithinTheThreshold) {
    const Model model = load_model(test::fzk_haus_ifc);
    LodParameters p = small_chain_parameters();
    p.resolution = 256;
    Chain chain(model, p, 2);
    for (double threshold : {0.02, 0.2}) {
        const SwitchedChain switched = switched_levels(chain, threshold, 100);
        ASSERT_GE(switched.levels.size(), 1u);
        ASSERT_EQ(switched.errors.size(), switched.levels.size());
        EXPECT_EQ(switched.levels[0].level, 0);
        EXPECT_EQ(switched.switch_distances[0], 0);
        for (std::size_t k = 1; k < switched.levels.size(); ++k) {
            EXPECT_GT(switched.switch_distances[k], switched.switch_distances[k - 1]);
            EXPECT_LT(combined_cost({&switched.levels[k].lod.cost}).bytes(),
                      combined_cost({&switched.levels[k - 1].lod.cost}).bytes());
            for (std::size_t d = 0; d < switched.distances.size(); ++d)
                if (switched.distances[d] >= switched.switch_distances[k]) {
                    EXPECT_LE(switched.errors[k][d], threshold);
                }
        }
        if (threshold > 0.1) {
            EXPECT_GE(switched.levels.size(), 2u);  // a lenient threshold reaches boxes
        }
    }
    const SwitchedChain sized = switched_levels(chain, 0, 100);
    EXPECT_TRUE(sized.errors.empty());
    for (std::size_t k = 1; k < sized.levels.size(); ++k)
        EXPECT_EQ(sized.switch_distances[k], chain.sized_parameters(sized.levels[k].level).distance);
    EXPECT_EQ(switched_levels(chain, 0, 2).levels.size(), 2u);  // the cap
    LodParameters manual = p;  // every level sized for one distance: switched where auto distances put them
    set_manual(manual);
    manual.max_texture_size = 256;
    Chain same(model, manual, 2);
    const SwitchedChain texels = switched_levels(same, 0, 100);
    EXPECT_GE(texels.levels.size(), 3u);
    for (std::size_t k = 1; k < texels.levels.size(); ++k)
        EXPECT_EQ(texels.switch_distances[k],
                  doubled_distance(same.parameters().distance, texels.levels[k].level));
}

// Under --manual a ladder finer than halvings switches where auto sizing would put its levels:
// capped by the budgets, not doubled out to where the building is a pixel.
TEST(Chain, SameSizedBudgetLevelsSwitchWhereAutoCapsThem) {
    const Model model = load_model(test::fzk_haus_ifc);
    LodParameters p = small_chain_parameters();
    set_manual(p);
    p.max_texture_size = 256;
    p.level_mode = LevelMode::error_greedy;
    p.budgets = {{true, 0.5}, {true, 0.4}, {true, 0.3}};
    Chain chain(model, p, 2);
    ASSERT_EQ(chain.obtained_levels(), 3);
    const std::vector<float> automatic = level_distances({}, chain.parameters().distance, 3, p.budgets);
    const SwitchedChain switched = switched_levels(chain, 0, 100);
    ASSERT_GT(switched.levels.back().level, 1);  // a level the doubling would size farther
    for (std::size_t k = 1; k < switched.levels.size(); ++k) {
        const int c = switched.levels[k].level;
        EXPECT_EQ(switched.switch_distances[k], automatic[std::size_t(c - 1)]) << c;
        if (c > 1) {
            EXPECT_LT(switched.switch_distances[k], doubled_distance(chain.parameters().distance, c)) << c;
        }
    }
}
