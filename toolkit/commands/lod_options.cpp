#include "toolkit/commands/lod_options.h"

#include "base/input_error.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/parameter_file.h"

#include <algorithm>
#include <filesystem>
#include <string_view>

namespace boxlod {
namespace {

Option option_of(const ParameterDeclaration& d) { return {d.option, d.value_name, d.help_text(), d.range}; }

bool among(const ParameterDeclaration& d, const std::vector<std::string>& keys) {
    return std::find_if(keys.begin(), keys.end(), [&](const std::string& key) { return d.key == key; }) !=
           keys.end();
}

bool is_parameter_file(const std::string& path) { return std::filesystem::path(path).extension() == ".txt"; }

}  // namespace

std::vector<Option> lod_options() {
    std::vector<Option> options{{"params", "FILE", "load only the parameters from FILE (the model is MODEL)"},
                                {"manual", "",
                                 "the manual's program instead of the chain that pays its way: every level "
                                 "at one sizing distance, every sub-tree boxed, pages of at least 256 "
                                 "texels, no flat faces (other options change single parameters)"}};
    for (const ParameterDeclaration& d : lod_parameter_declarations()) options.push_back(option_of(d));
    return options;
}

std::vector<Option> lod_options(const std::vector<std::string>& keys) {
    std::vector<Option> options;
    for (const ParameterDeclaration& d : lod_parameter_declarations())
        if (among(d, keys)) options.push_back(option_of(d));
    return options;
}

void apply_lod_options(const Arguments& a, LodParameters& p, const std::vector<std::string>& keys) {
    for (const ParameterDeclaration& d : lod_parameter_declarations()) {
        if (!a.has(d.option) || (keys.size() > 0 && !among(d, keys))) continue;
        // A flag sets the opposite of the default (--keep-small-subtrees, --no-crop).
        std::string value =
            d.is_flag() ? (d.format(LodParameters{}) == "true" ? "false" : "true") : a.text(d.option);
        if (std::string problem = d.parse(value, p); !problem.empty())
            throw InputError("--" + d.option + ": " + problem);
    }
}

// The parameters come from a file (the input, or --params), then --manual,
// then each option given: what the command line says wins.
LodParameters lod_parameters_from(const Arguments& a) {
    LodParameters p;
    const std::string& input = a.positionals[0];
    if (is_parameter_file(input)) {
        if (a.has("params"))
            throw InputError("--params: " + input +
                             " is a parameter file already (--params takes the parameters for a model)");
        p = load_parameters(input);
        if (p.model.empty()) throw_input_error(input, "", "the parameter file names no model (key 'model')");
    } else {
        if (a.has("params")) p = load_parameters(a.text("params"));
        p.model = input;
    }
    if (a.has("manual")) set_manual(p);
    apply_lod_options(a, p);
    validate_parameters(p, "command line");
    return p;
}

Model load_parameters_model(const LodParameters& parameters) {
    return load_model(parameters.model, {.chain_level = 0, .city_lod = parameters.city_lod});
}

Option city_lod_option() { return option_of(*find_lod_parameter("city_lod")); }

std::string city_lod_from(const Arguments& arguments) {
    LodParameters parameters;
    apply_lod_options(arguments, parameters, {"city_lod"});
    return parameters.city_lod;
}

}  // namespace boxlod
