#include "data_gen/city.h"

#include "base/input_error.h"
#include "data_gen/grammar_parser.h"
#include "base/random.h"
#include "data_gen/samples.h"

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

Model generate_city(const CityOptions& options) {
    if (options.buildings < 1) throw InputError("--city: the number of buildings must be at least 1");
    if (options.kinds.empty()) throw InputError("city: no building kinds to choose from");
    std::vector<Grammar> kinds;
    Eigen::Vector2f largest_lot = Eigen::Vector2f::Zero();
    for (const std::string& kind : options.kinds) {
        kinds.push_back(sample_grammar(kind));
        largest_lot = largest_lot.cwiseMax(default_lot(kinds.back(), options.seed));
    }
    Grammar streets = parse_grammar(street_grammar, "city streets");

    // Lots vary by up to 15% around their grammar's size; a cell holds the largest.
    const float variation = 0.15f;
    Eigen::Vector2f cell = largest_lot * (1 + variation) + Eigen::Vector2f::Constant(4);
    int columns = int(std::ceil(std::sqrt(double(options.buildings))));
    int rows = (options.buildings + columns - 1) / columns;
    float street = options.street_width;
    Eigen::Vector2f city_size(columns * cell.x() + (columns + 1) * street, rows * cell.y() + (rows + 1) * street);

    Model model;
    model.source = "city";
    MaterialCache materials;
    int root = add_node(model, -1, "City");
    model.nodes[root].rule = "City";
    model.nodes[root].scope = to_scope(ground_lot(city_size.x(), city_size.y()));
    Eigen::Vector3f corner(-city_size.x() / 2, 0, -city_size.y() / 2);

    int street_node = add_node(model, root, "Streets");
    model.nodes[street_node].scope = model.nodes[root].scope;
    auto add_street = [&](float x, float z, float width, float depth) {
        Eigen::Vector3f center = corner + Eigen::Vector3f(x + width / 2, 0, z + depth / 2);
        derive(streets, "", ground_lot(width, depth, center), options.seed, model, street_node, materials, options.limits);
    };
    // Streets along x run the whole width; those along z fill the gaps between them.
    for (int r = 0; r <= rows; ++r) add_street(0, r * (cell.y() + street), city_size.x(), street);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c <= columns; ++c)
            add_street(c * (cell.x() + street), street + r * (cell.y() + street), street, cell.y());

    for (int i = 0; i < options.buildings; ++i) {
        int row = i / columns, column = i % columns;
        std::uint64_t identity = hash_combine(options.seed, std::uint64_t(i));
        Pcg32 random(options.seed, identity);
        std::size_t kind = std::min(kinds.size() - 1, std::size_t(random.uniform() * kinds.size()));
        std::uint64_t building_seed = random.next_uint();
        Eigen::Vector2f lot = default_lot(kinds[kind], building_seed);
        lot.x() *= float(random.uniform(1 - variation, 1 + variation));
        lot.y() *= float(random.uniform(1 - variation, 1 + variation));
        lot = lot.cwiseMin(cell - Eigen::Vector2f::Constant(4));
        Eigen::Vector3f center = corner + Eigen::Vector3f(street + column * (cell.x() + street) + cell.x() / 2, 0,
                                                          street + row * (cell.y() + street) + cell.y() / 2);
        derive(streets, "Block", ground_lot(cell.x(), cell.y(), center), options.seed, model, street_node, materials,
               options.limits);
        int building = derive(kinds[kind], "", ground_lot(lot.x(), lot.y(), center), building_seed, model, root, materials,
                              options.limits);
        model.nodes[building].name = options.kinds[kind] + "_" + std::to_string(i);
    }
    return model;
}

double city_file_memory(int buildings) { return 16e6 * double(buildings); }

}  // namespace boxlod
