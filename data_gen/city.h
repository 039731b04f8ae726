// A city: a grid of lots separated by streets, each lot holding one building
// from a sample grammar, its kind and seed drawn per lot.
#pragma once
#include "data_gen/interpreter.h"
#include "toolkit/model/model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace boxlod {

struct CityOptions {
    int buildings = 9;
    std::uint64_t seed = 0;
    float street_width = 10;                                        // metres
    std::vector<std::string> kinds = {"house", "office", "classical"};  // sample grammars to draw from
    DerivationLimits limits;                                        // per building
};

// The root "City" holds a "Streets" node (a "Street" node per street
// segment and a paved "Block" per lot, with geometry) and one derivation tree
// per building. The grid has
// ceil(sqrt(buildings)) columns; lot i is row i / columns, column i % columns.
Model generate_city(const CityOptions& options);

// What `generate --city` needs to make a city and write it: 16 MB a building
// (its peak resident with 100, 200 and 400 buildings: 15.6, 14.9 and 16.0 MB
// each; the model alone is a sixth of it, the rest the glTF being written).
double city_file_memory(int buildings);

}  // namespace boxlod
