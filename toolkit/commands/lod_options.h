// The LoD options `build`, `view`, `levels`, `render` and `city` share, made
// from the parameters' declarations (toolkit/lod/lod_parameters.h), and the
// parameters they give: a parameter file first (MODEL|PARAMS.txt, or --params
// for parameters only), then every option given on the command line on top.
#pragma once
#include "base/command_line.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/model/model.h"

#include <string>
#include <vector>

namespace boxlod {

std::vector<Option> lod_options();  // --params and every LoD parameter
// The options of the parameters with these keys, in declaration order.
std::vector<Option> lod_options(const std::vector<std::string>& keys);
// Sets every declared LoD parameter whose option is given (of those with these
// keys; empty: all); throws InputError.
void apply_lod_options(const Arguments& arguments, LodParameters& parameters,
                       const std::vector<std::string>& keys = {});
LodParameters lod_parameters_from(const Arguments& arguments);

// The model the parameters name, read as they say (a CityJSON model's LoD).
Model load_parameters_model(const LodParameters& parameters);
// For the commands that read a model without the LoD options (info, convert,
// render): --city-lod, declared with the parameter (toolkit/lod/lod_parameters.h).
Option city_lod_option();
std::string city_lod_from(const Arguments& arguments);

}  // namespace boxlod
