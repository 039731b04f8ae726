#include "data_gen/city.h"

#include "base/input_error.h"

#include <gtest/gtest.h>

#include <set>

namespace boxlod {

namespace {

// The footprint (x, z) of a node's scope, as min and max corners.
std::pair<Eigen::Vector2f, Eigen::Vector2f> footprint(const Node& node) {
    Eigen::Vector3f lo = node.scope->center - node.scope->axes.cwiseAbs() * node.scope->half_extents;
    Eigen::Vector3f hi = node.scope->center + node.scope->axes.cwiseAbs() * node.scope->half_extents;
    return {{lo.x(), lo.z()}, {hi.x(), hi.z()}};
}

}  // namespace

TEST(City, StreetsAndOneTreePerBuilding) {
    CityOptions options;
    options.buildings = 4;
    Model city = generate_city(options);
    EXPECT_EQ(city.nodes[0].name, "City");
    const Node& streets = city.nodes[1];
    EXPECT_EQ(streets.name, "Streets");
    std::vector<int> buildings(city.nodes[0].children.begin() + 1, city.nodes[0].children.end());
    ASSERT_EQ(buildings.size(), 4u);
    int street_count = 0, block_count = 0;
    for (int child : streets.children) {
        const Node& ground = city.nodes[child];
        EXPECT_TRUE(ground.has_geometry());
        block_count += ground.rule == "Block";
        if (ground.rule != "Street") continue;
        ++street_count;
        auto [s_lo, s_hi] = footprint(ground);
        for (int building : buildings) {
            auto [b_lo, b_hi] = footprint(city.nodes[building]);
            bool apart =
                (b_hi.array() <= s_lo.array() + 1e-3f).any() || (s_hi.array() <= b_lo.array() + 1e-3f).any();
            EXPECT_TRUE(apart) << city.nodes[building].name << " overlaps a street";
        }
    }
    EXPECT_EQ(street_count, 9);  // 2 x 2 lots: 3 streets along x, 2 rows of 3 between
    EXPECT_EQ(block_count, 4);
    for (int i = 0; i < 4; ++i) {
        const std::string& name = city.nodes[buildings[i]].name;
        EXPECT_EQ(name.substr(name.find('_') + 1), std::to_string(i));
    }
    EXPECT_NO_THROW(validate_model(city));
}

TEST(City, SeedDecidesKindsDeterministically) {
    CityOptions options;
    options.buildings = 12;
    options.seed = 4;
    Model a = generate_city(options), b = generate_city(options);
    options.seed = 5;
    Model c = generate_city(options);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) EXPECT_EQ(a.nodes[i].name, b.nodes[i].name);
    EXPECT_NE(a.nodes.size(), c.nodes.size());
    std::set<std::string> kinds;
    for (std::size_t i = 1; i < a.nodes[0].children.size(); ++i) {
        const std::string& name = a.nodes[a.nodes[0].children[i]].name;
        kinds.insert(name.substr(0, name.find('_')));
    }
    EXPECT_GE(kinds.size(), 2u);
}

TEST(City, ALotKeepsItsBuildingWhenTheCityGrows) {
    // Each lot draws from its own stream: lot 0 is the same building in a city of 2 and of 9.
    CityOptions small, large;
    small.buildings = 2;
    large.buildings = 9;
    Model a = generate_city(small), b = generate_city(large);
    int first_a = a.nodes[0].children[1], first_b = b.nodes[0].children[1];
    EXPECT_EQ(a.nodes[first_a].name, b.nodes[first_b].name);
    EXPECT_EQ(a.nodes[first_a].scope->half_extents, b.nodes[first_b].scope->half_extents);
}

TEST(City, NeedsAtLeastOneBuildingAndDesignsInRange) {
    CityOptions options;
    options.buildings = 0;
    EXPECT_THROW(generate_city(options), InputError);
    options.buildings = 4;
    options.designs = -1;
    EXPECT_THROW(plan_city(options), InputError);
    options.designs = 10001;
    EXPECT_THROW(plan_city(options), InputError);
}

// With K designs every lot shows one of them, each building is its design
// moved to the lot, and a lot's design does not depend on the city's size.
TEST(City, LotsDrawFromTheDesignsAndShowThemInPlace) {
    CityOptions options;
    options.buildings = 16;
    options.designs = 3;
    CityPlan plan = plan_city(options);
    ASSERT_EQ(plan.designs.size(), 3u);
    std::set<std::size_t> shown;
    for (const CityLot& lot : plan.lots) shown.insert(lot.design);
    EXPECT_EQ(shown.size(), 3u);
    Model city = generate_city(options);
    for (std::size_t i = 0; i < plan.lots.size(); ++i) {
        const CityLot& lot = plan.lots[i];
        const Node& placed = city.nodes[std::size_t(city.nodes[0].children[i + 1])];
        EXPECT_EQ(placed.name, lot.name);
        Model design = design_model(plan, lot.design, lot.name);
        ASSERT_EQ(design.nodes[0].scope.has_value(), placed.scope.has_value());
        EXPECT_LT((design.nodes[0].scope->center + lot.center - placed.scope->center).norm(), 1e-3f)
            << lot.name;
        EXPECT_EQ(design.nodes[0].scope->half_extents, placed.scope->half_extents);
    }
    options.buildings = 5;
    CityPlan smaller = plan_city(options);
    for (std::size_t i = 0; i < smaller.lots.size(); ++i)
        EXPECT_EQ(smaller.lots[i].design, plan.lots[i].design);
    options.designs = 0;
    EXPECT_EQ(plan_city(options).designs.size(), 5u);  // each lot its own
}

}  // namespace boxlod

namespace boxlod {
namespace {

// A generated city read back as a file city: its lots are the root's children
// with geometry (the streets too, as one object), each centred on its lot.
TEST(City, AModelsObjectsAreTheLotsOfAFileCity) {
    CityOptions options;
    options.buildings = 4;
    const Model city = generate_city(options);
    const CityPlan plan = plan_from_model(city);
    ASSERT_EQ(plan.lots.size(), plan.given_designs.size());
    EXPECT_EQ(plan.lots.size(), city.nodes[0].children.size());
    EXPECT_TRUE(city_streets(plan).nodes[0].primitives.empty());
    Bounds whole = model_bounds(city);
    for (std::size_t i = 0; i < plan.lots.size(); ++i) {
        const Model design = design_model(plan, plan.lots[i].design, "d");
        EXPECT_EQ(design.nodes[0].name, "d");
        const Bounds bounds = model_bounds(design);
        // Centred on its lot, standing on the ground plane at y = 0.
        EXPECT_NEAR(bounds.center().x(), 0, 1e-3);
        EXPECT_NEAR(bounds.center().z(), 0, 1e-3);
        EXPECT_NEAR(bounds.min.y(), 0, 1e-3);
        EXPECT_TRUE(((bounds.max + plan.lots[i].center).array() <= whole.max.array() + 1e-3f).all());
    }
    EXPECT_NEAR(plan.size.x(), whole.size().x(), 1e-3);
}

}  // namespace
}  // namespace boxlod
