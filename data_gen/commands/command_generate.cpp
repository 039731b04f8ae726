#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/distinct_files.h"
#include "base/memory_budget.h"
#include "data_gen/city.h"
#include "data_gen/commands/commands.h"
#include "data_gen/grammar_parser.h"
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "toolkit/boxlod.h"
#include "toolkit/model/statistics.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace boxlod {

namespace {

// "WxD" in metres, both positive.
Eigen::Vector2f parse_lot(const std::string& text) {
    std::size_t x = text.find('x');
    float width = 0, depth = 0;
    bool ok = x != std::string::npos;
    if (ok) {
        auto [w_end, w_error] = std::from_chars(text.data(), text.data() + x, width);
        auto [d_end, d_error] = std::from_chars(text.data() + x + 1, text.data() + text.size(), depth);
        ok = w_error == std::errc() && d_error == std::errc() && w_end == text.data() + x &&
             d_end == text.data() + text.size() && std::isfinite(width) && std::isfinite(depth) &&
             width > 0 && depth > 0;
    }
    if (!ok)
        throw InputError("boxlod generate: --lot: expected WIDTHxDEPTH in metres, e.g. 20x15, got '" + text +
                         "'");
    return {width, depth};
}

int run_generate(const Arguments& arguments) {
    const char* prefix = "boxlod generate: ";
    int sources = int(arguments.positionals.size()) + arguments.has("sample") + arguments.has("city");
    if (sources != 1)
        throw InputError(std::string(prefix) + "give exactly one of GRAMMAR, --sample NAME or --city N");
    if (!arguments.has("output"))
        throw InputError(std::string(prefix) + "-o/--output OUT.gltf|OUT.glb is required");
    check_output_file(arguments.text("output"), {".gltf", ".glb"});
    if (!arguments.positionals.empty())
        check_distinct_files({{"GRAMMAR", arguments.positionals[0]}},
                             {{"--output", arguments.text("output")}});
    const int seed = arguments.integer("seed");

    Model model;
    KeyValues report = {text_entry("output", arguments.text("output")), number_entry("seed", seed)};
    if (arguments.has("designs") && !arguments.has("city"))
        throw InputError(std::string(prefix) + "--designs applies to --city only");
    if (arguments.has("city")) {
        if (arguments.has("start") || arguments.has("lot"))
            throw InputError(std::string(prefix) + "--start and --lot apply to one building, not to --city");
        CityOptions city;
        city.buildings = arguments.integer("city", 0);
        city.designs = arguments.integer("designs");
        check_memory(std::string(prefix) + "a city of " + std::to_string(city.buildings) + " buildings",
                     city_file_memory(city.buildings));
        city.seed = std::uint64_t(seed);
        model = generate_city(city);
        report.push_back(number_entry("buildings", city.buildings));
    } else {
        Grammar grammar = arguments.has("sample") ? sample_grammar(arguments.text("sample"))
                                                  : read_grammar(arguments.positionals[0]);
        BuildingOptions building;
        building.start = arguments.text("start");
        if (arguments.has("lot")) building.lot = parse_lot(arguments.text("lot"));
        building.seed = std::uint64_t(seed);
        model = generate_building(grammar, building);
    }
    // A .gltf's texture files are named after the model (house_brick_color.png beside house.gltf),
    // so two models written into one folder never overwrite each other's.
    const std::filesystem::path output = arguments.text("output");
    if (output.extension() == ".gltf")
        for (Texture& texture : model.textures) texture.name = output.stem().string() + "_" + texture.name;
    write_model(model, arguments.text("output"));
    for (KeyValue& entry : model_statistics(model)) report.push_back(std::move(entry));
    print_report(report, arguments);
    return 0;
}

}  // namespace

Option designs_option() {
    return {"designs", "K",
            "with --city: the lots draw from K distinct building designs (0: each lot its own)",
            city_designs_range, std::to_string(CityOptions{}.designs)};
}

Subcommand generate_subcommand() {
    return {
        {"generate",
         "[GRAMMAR]",
         "Generate a building from a shape grammar (a file, or a built-in sample), or a whole city, and "
         "write it as glTF with its derivation tree, scopes and rules. The same grammar and seed give "
         "byte-identical files.",
         {{"sample", "NAME", "use a built-in sample grammar: " + sample_names()},
          {"city", "N", "generate a city of N buildings on a grid of lots with streets",
           city_buildings_range},
          designs_option(),
          {"start", "SYMBOL", "the rule to start from (default: the grammar's first rule)"},
          {"lot", "WxD",
           "the lot's width and depth in metres (default: the grammar's lot_width/lot_depth, else 20x20)"},
          {"seed", "S", "seed of the random choices", seed_range, std::to_string(CityOptions{}.seed)},
          {"output", "FILE", "output file, .gltf or .glb (required)", {}, "", 'o'},
          json_option()},
         0,
         1},
        run_generate};
}

}  // namespace boxlod
