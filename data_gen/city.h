// A city: a grid of lots separated by streets, each lot holding one building
// from a sample grammar, its kind and seed drawn per lot.
#pragma once
#include "data_gen/grammar.h"
#include "data_gen/interpreter.h"
#include "toolkit/model/model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace boxlod {

struct CityOptions {
    int buildings = 9;
    std::uint64_t seed = 0;
    float street_width = 10;                                            // metres
    std::vector<std::string> kinds = {"house", "office", "classical"};  // sample grammars to draw from
    // Distinct building designs the lots draw from (as a city repeats its
    // catalogue of houses); 0: every lot a design of its own.
    int designs = 0;
    DerivationLimits limits;  // per building
};
constexpr NumberRange city_buildings_range{1, 10000};
constexpr NumberRange city_designs_range{0, 10000};

// What a building is: a sample grammar (an index into CityOptions::kinds), the
// seed of its derivation and its lot's width and depth.
struct BuildingDesign {
    std::size_t kind = 0;
    std::uint64_t seed = 0;
    Eigen::Vector2f lot = Eigen::Vector2f::Zero();
};

// A lot of the grid: its building's name and design, and the centre of the lot on the ground.
struct CityLot {
    std::string name;  // kind_i for lot i
    std::size_t design = 0;
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
};

// The city before anything is derived: the grid has ceil(sqrt(buildings))
// columns; lot i is row i / columns, column i % columns. Each lot draws its
// design from its own seeded stream, so a lot keeps its building when the city grows.
struct CityPlan {
    CityOptions options;
    std::vector<Grammar> kinds;
    std::vector<BuildingDesign> designs;
    std::vector<CityLot> lots;
    Eigen::Vector2f cell = Eigen::Vector2f::Zero();  // a lot's cell: the largest lot and a margin
    Eigen::Vector2f size = Eigen::Vector2f::Zero();  // the whole city, streets included
    // A city read from a file: its objects as designs, each centred on its lot (no grammar, no streets).
    std::vector<Model> given_designs;
};
CityPlan plan_city(const CityOptions& options);
// A city model read from a file (a CityJSON district, a glTF city): each
// object (toolkit/model/model_subtree.h: object_nodes) is a design of its own,
// moved to the origin, on a lot at the middle of its footprint, on its ground.
CityPlan plan_from_model(const Model& city);
int city_rows(const CityPlan& plan);
int city_columns(const CityPlan& plan);
// The middle of street r along x (r = 0..rows, in order of z), on the ground;
// each runs the city's whole width.
Eigen::Vector3f street_along_x(const CityPlan& plan, int r);

// The root "City" holding a "Streets" node only: a "Street" node per street
// segment and a paved "Block" per lot, with geometry (none for a city read from a file).
Model city_streets(const CityPlan& plan);

// A design's derivation tree on a lot centred at the origin, its root named
// `name`: a lot's building is this model moved to the lot's centre.
Model design_model(const CityPlan& plan, std::size_t design, const std::string& name);

// The whole city in one model: the streets, and one derivation tree per lot,
// derived in place under the root.
Model generate_city(const CityOptions& options);

// What `generate --city` needs to make a city and write it: 16 MB a building,
// its measured peak resident per building (the model a sixth of it, the rest
// the glTF being written; docs/city.md: Scale).
double city_file_memory(int buildings);

}  // namespace boxlod
