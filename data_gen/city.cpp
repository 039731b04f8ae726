#include "data_gen/city.h"

#include "base/input_error.h"
#include "base/random.h"
#include "data_gen/grammar_parser.h"
#include "data_gen/samples.h"
#include "toolkit/model/model_subtree.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

namespace {

// Streets and the pavement of each block are derived like buildings, from
// this grammar: the top face of a flat piece of ground, paved.
const char* const street_grammar =
    "Street --> comp(f) { top : material(asphalt) i(quad) }\n"
    "Block --> comp(f) { top : material(concrete) color(\"#b4b2aa\") i(quad) }\n";

}  // namespace

namespace {

// The street pieces and blocks are flat lots: derived where they lie.
void derive_ground(const CityPlan& plan, const Grammar& streets, const std::string& start,
                   const ScopeBox& lot, Model& model, int parent, MaterialCache& materials) {
    derive(streets, start, lot, plan.options.seed, model, parent, materials, plan.options.limits);
}

// A design drawn from a stream: its kind, its derivation's seed and its lot,
// up to 15 % around its grammar's size and within the cell.
BuildingDesign draw_design(const CityPlan& plan, Pcg32& random, float variation) {
    BuildingDesign design;
    const std::size_t kinds = plan.kinds.size();
    design.kind = std::min(kinds - 1, std::size_t(random.uniform() * double(kinds)));
    design.seed = random.next_uint();
    Eigen::Vector2f lot = default_lot(plan.kinds[design.kind], design.seed);
    lot.x() *= float(random.uniform(1 - variation, 1 + variation));
    lot.y() *= float(random.uniform(1 - variation, 1 + variation));
    design.lot = lot.cwiseMin(plan.cell - Eigen::Vector2f::Constant(4));
    return design;
}

}  // namespace

CityPlan plan_city(const CityOptions& options) {
    if (!city_buildings_range.contains(options.buildings))
        throw InputError("--city: the number of buildings must be in " + range_text(city_buildings_range));
    if (!city_designs_range.contains(options.designs))
        throw InputError("--designs: the number of designs must be in " + range_text(city_designs_range));
    if (options.kinds.empty()) throw InputError("city: no building kinds to choose from");
    CityPlan plan;
    plan.options = options;
    Eigen::Vector2f largest_lot = Eigen::Vector2f::Zero();
    for (const std::string& kind : options.kinds) {
        plan.kinds.push_back(sample_grammar(kind));
        largest_lot = largest_lot.cwiseMax(default_lot(plan.kinds.back(), options.seed));
    }
    // Lots vary by up to 15% around their grammar's size; a cell holds the largest.
    const float variation = 0.15f;
    plan.cell = largest_lot * (1 + variation) + Eigen::Vector2f::Constant(4);
    const int columns = int(std::ceil(std::sqrt(double(options.buildings))));
    const int rows = (options.buildings + columns - 1) / columns;
    const float street = options.street_width;
    plan.size = {columns * plan.cell.x() + (columns + 1) * street,
                 rows * plan.cell.y() + (rows + 1) * street};
    const Eigen::Vector3f corner(-plan.size.x() / 2, 0, -plan.size.y() / 2);

    // Shared designs draw from streams of their own, apart from the lots'.
    const std::uint64_t design_streams = hash_combine(options.seed, 0x64657369676e73ull);  // "designs"
    for (int d = 0; d < options.designs; ++d) {
        Pcg32 random(options.seed, hash_combine(design_streams, std::uint64_t(d)));
        plan.designs.push_back(draw_design(plan, random, variation));
    }
    for (int i = 0; i < options.buildings; ++i) {
        const int row = i / columns, column = i % columns;
        Pcg32 random(options.seed, hash_combine(options.seed, std::uint64_t(i)));
        CityLot lot;
        if (options.designs == 0) {
            lot.design = plan.designs.size();
            plan.designs.push_back(draw_design(plan, random, variation));
        } else {
            lot.design =
                std::min(std::size_t(options.designs) - 1, std::size_t(random.uniform() * options.designs));
        }
        lot.name = options.kinds[plan.designs[lot.design].kind] + "_" + std::to_string(i);
        lot.center = corner + Eigen::Vector3f(street + column * (plan.cell.x() + street) + plan.cell.x() / 2,
                                              0, street + row * (plan.cell.y() + street) + plan.cell.y() / 2);
        plan.lots.push_back(std::move(lot));
    }
    return plan;
}

namespace {

Model make_streets(const CityPlan& plan, MaterialCache& materials) {
    Grammar streets = parse_grammar(street_grammar, "city streets");
    Model model;
    model.source = "city";
    int root = add_node(model, -1, "City");
    model.nodes[root].rule = "City";
    model.nodes[root].scope = to_scope(ground_lot(plan.size.x(), plan.size.y()));
    const Eigen::Vector3f corner(-plan.size.x() / 2, 0, -plan.size.y() / 2);
    const Eigen::Vector2f cell = plan.cell;
    const int columns = city_columns(plan), rows = city_rows(plan);
    const float street = plan.options.street_width;

    int street_node = add_node(model, root, "Streets");
    model.nodes[street_node].scope = model.nodes[root].scope;
    auto add_street = [&](float x, float z, float width, float depth) {
        Eigen::Vector3f center = corner + Eigen::Vector3f(x + width / 2, 0, z + depth / 2);
        derive_ground(plan, streets, "", ground_lot(width, depth, center), model, street_node, materials);
    };
    // Streets along x run the whole width; those along z fill the gaps between them.
    for (int r = 0; r <= rows; ++r) {
        const Eigen::Vector3f middle = street_along_x(plan, r);
        derive_ground(plan, streets, "", ground_lot(plan.size.x(), street, middle), model, street_node,
                      materials);
    }
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c <= columns; ++c)
            add_street(c * (cell.x() + street), street + r * (cell.y() + street), street, cell.y());
    for (const CityLot& lot : plan.lots)
        derive_ground(plan, streets, "Block", ground_lot(cell.x(), cell.y(), lot.center), model, street_node,
                      materials);
    return model;
}

// A design's building derived under `parent` on its lot centred at `center`.
int derive_design(const CityPlan& plan, std::size_t design, const Eigen::Vector3f& center, Model& model,
                  int parent, MaterialCache& materials, const std::string& name) {
    const BuildingDesign& d = plan.designs.at(design);
    int building = derive(plan.kinds[d.kind], "", ground_lot(d.lot.x(), d.lot.y(), center), d.seed, model,
                          parent, materials, plan.options.limits);
    model.nodes[building].name = name;
    return building;
}

}  // namespace

int city_columns(const CityPlan& plan) { return int(std::ceil(std::sqrt(double(plan.lots.size())))); }
int city_rows(const CityPlan& plan) {
    const int columns = city_columns(plan);
    return (int(plan.lots.size()) + columns - 1) / columns;
}

Eigen::Vector3f street_along_x(const CityPlan& plan, int r) {
    const float street = plan.options.street_width;
    return {0, 0, -plan.size.y() / 2 + (float(r) * (plan.cell.y() + street) + street / 2)};
}

Model city_streets(const CityPlan& plan) {
    if (!plan.given_designs.empty()) {
        Model model;
        model.source = "city";
        add_node(model, -1, "City");
        return model;
    }
    MaterialCache materials;
    return make_streets(plan, materials);
}

Model design_model(const CityPlan& plan, std::size_t design, const std::string& name) {
    if (!plan.given_designs.empty()) {
        Model model = plan.given_designs[design];
        model.nodes[0].name = name;
        return model;
    }
    Model model;
    model.source = "city";
    MaterialCache materials;
    derive_design(plan, design, Eigen::Vector3f::Zero(), model, -1, materials, name);
    return model;
}

Model generate_city(const CityOptions& options) {
    CityPlan plan = plan_city(options);
    MaterialCache materials;  // one for the whole model: each material and texture once
    Model model = make_streets(plan, materials);
    for (const CityLot& lot : plan.lots)
        derive_design(plan, lot.design, lot.center, model, 0, materials, lot.name);
    return model;
}

double city_file_memory(int buildings) { return 16e6 * double(buildings); }

CityPlan plan_from_model(const Model& city) {
    CityPlan plan;
    plan.options.buildings = 0;
    Bounds whole;
    for (int node : object_nodes(city)) {
        Model design = object_model(city, node);
        const Bounds bounds = model_bounds(design);
        const Eigen::Vector3f center(bounds.center().x(), bounds.min.y(), bounds.center().z());
        for (Node& n : design.nodes) {
            for (Primitive& p : n.primitives)
                for (Eigen::Vector3f& position : p.positions) position -= center;
            if (n.scope) n.scope->center -= center;
        }
        plan.lots.push_back({design.nodes[0].name, plan.given_designs.size(), center});
        plan.designs.push_back({});
        plan.given_designs.push_back(std::move(design));
        plan.cell = plan.cell.cwiseMax(Eigen::Vector2f(bounds.size().x(), bounds.size().z()));
        whole.add(bounds.min);
        whole.add(bounds.max);
    }
    plan.options.buildings = int(plan.lots.size());
    plan.size = Eigen::Vector2f(whole.size().x(), whole.size().z());
    return plan;
}

}  // namespace boxlod
