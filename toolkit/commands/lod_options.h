// The LoD options `build` and `view` share, and the parameters they give:
// a parameter file first (MODEL|PARAMS.txt, or --params for parameters only),
// then every option given on the command line on top.
#pragma once
#include "base/command_line.h"
#include "toolkit/parameters.h"

namespace boxlod {

std::vector<Option> lod_options();
LodParameters lod_parameters_from(const Arguments& arguments);

}  // namespace boxlod
