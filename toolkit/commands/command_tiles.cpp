#include "base/atomic_write.h"
#include "base/common_options.h"
#include "base/distinct_files.h"
#include "base/input_error.h"
#include "base/parallel.h"
#include "toolkit/commands/commands.h"
#include "toolkit/commands/lod_options.h"
#include "toolkit/formats/gltf_io.h"
#include "toolkit/formats/map_projection.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/formats/tileset.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/chain/switch_measures.h"
#include "toolkit/lod/hybrid/draw_calls.h"
#include "toolkit/lod/pages/boxes.h"
#include "toolkit/lod/surface_deviation.h"
#include "toolkit/model/model_subtree.h"

#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <regex>

namespace boxlod {
namespace {

constexpr NumberRange latitude_range{-90, 90}, longitude_range{-180, 180}, height_range{-11000, 100000};

// One object's chain (chain.h: switched_levels), as OUTDIR/object_K_L<c>.glb,
// with a geometric error from the level's switch distance and measured
// deviation that makes clients switch where a chain does at the latest
// (level_geometric_error).
TileObject build_object(const Model& model, int index, const LodParameters& parameters, double switch_error,
                        bool keep_hierarchy, const std::string& folder) {
    Chain chain(model, parameters, 1);
    // The bounding volume encloses the geometry whatever box kind the levels use.
    TileObject object{model.nodes[0].name, *node_boxes(model, BoxKind::expanded, 1)[0], {}};
    std::vector<int> levels;
    for (int c = 1; c <= chain.obtained_levels(); ++c) levels.push_back(c);
    check_chain_budgets(chain, levels);
    const SurfaceViews original = surface_views(model, object.box);
    SwitchedChain switched = switched_levels(chain, switch_error, std::numeric_limits<int>::max());
    for (std::size_t k = 0; k < switched.levels.size(); ++k) {
        ChainLevel& built = switched.levels[k];
        const std::string name = "object_" + std::to_string(index) + "_L" + std::to_string(built.level);
        TileLevel level{name + ".glb", 0, 0};
        if (k > 0) {
            level.surface_deviation = surface_deviation(original, surface_views(built.lod.model, object.box));
            level.geometric_error = level_geometric_error(switched.switch_distances[k],
                                                          chain.sizing(built.level), level.surface_deviation);
        }
        export_gltf(keep_hierarchy ? built.lod.model : merge_draw_calls(std::move(built.lod.model), name),
                    (std::filesystem::path(folder) / level.content).string(), 1);
        object.levels.push_back(std::move(level));
    }
    return object;
}

// What `tiles` writes into its folder: the tileset and its tiles.
bool is_tileset_file(const std::string& name) {
    static const std::regex tile(R"(object_\d+_L\d+\.glb)");
    return name == "tileset.json" || std::regex_match(name, tile);
}

// Where the tileset lies on the Earth, and by what ("default", "options", or the reference system).
struct Placement {
    Geodetic at;
    std::string by = "default";
};

void check_placement_options(const Arguments& a) {
    if (a.has("latitude") != a.has("longitude"))
        throw InputError(
            "--latitude and --longitude: give both or neither (the model's reference system, "
            "else KIT, Karlsruhe, places it)");
    if (a.has("latitude") && a.has("reference-system"))
        throw InputError(
            "--reference-system: the model is placed by --latitude and --longitude; give one or the other");
}

// The options' place, else the reference system's (--reference-system, else the file's) through PROJ,
// else KIT's; --height sets the height whatever places the rest.
Placement tileset_placement(const Arguments& a, const std::string& file_system,
                            const Eigen::Vector3d& source_origin, const std::string& model) {
    Placement placement;
    if (a.has("latitude")) {
        placement = {{a.number("latitude"), a.number("longitude"), 0}, "options"};
    } else if (const std::string system =
                   a.has("reference-system") ? a.text("reference-system") : file_system;
               !system.empty()) {
        const MapPlacement placed =
            place_on_earth(system, source_origin, a.has("reference-system") ? "--reference-system" : model);
        placement = {placed.at, system + " (PROJ: " + placed.operation + ")"};
    }
    if (a.has("height")) placement.at.height = a.number("height");
    return placement;
}

int run_tiles(const Arguments& a) {
    LodParameters parameters = lod_parameters_from(a);
    if (!a.has("output")) throw InputError("boxlod tiles: -o/--output OUTDIR is required");
    const std::filesystem::path folder = a.text("output");
    check_output_directory(folder.string());
    // A model (or parameter file) named like a tile in OUTDIR would be replaced, or removed with the old
    // tileset.
    for (const std::string& input : {model_file_of(parameters.model), a.positionals.at(0)})
        check_input_kept(input, folder.string(), is_tileset_file, "-o " + folder.string());
    check_placement_options(a);
    Model city = load_parameters_model(parameters);
    // A city file's offset goes to the tileset; each tile is local to the tileset's frame.
    const Eigen::Vector3d source_origin(city.origin.x(), -city.origin.z(),
                                        city.origin.y());  // y up to the file's z up
    const Placement placement = tileset_placement(a, city.reference_system, source_origin, parameters.model);
    const Geodetic& origin = placement.at;
    // The tiles' coordinates are the tileset frame's, at no system's origin: their glbs name none.
    city.origin = Eigen::Vector3d::Zero();
    city.reference_system.clear();
    const std::vector<int> nodes = object_nodes(city);
    Chain(object_model(city, nodes[0]), parameters, 1);  // bad parameters fail here, before any file
    const double error = switch_error(a);
    // The new tileset replaces a folder holding an old one in one step, so no
    // client ever loads a mix of two tilesets' tiles.
    OutputFolder output(folder.string(), is_tileset_file);
    OutputGroup files;  // every glb and the tileset naming them, or none
    std::vector<TileObject> objects(nodes.size());
    parallel_for(nodes.size(), threads_from(a), [&](std::size_t k) {
        objects[k] = build_object(object_model(city, nodes[k]), int(k), parameters, error,
                                  a.has("keep-hierarchy"), output.path());
    });
    write_text_atomically((std::filesystem::path(output.path()) / "tileset.json").string(),
                          tileset_json(objects, origin, source_origin));
    files.commit();
    output.commit();
    const std::string tileset = (folder / "tileset.json").string();
    std::size_t tiles = 0;
    for (const TileObject& object : objects) tiles += object.levels.size();
    std::printf("tileset = %s\nobjects = %zu\ntiles = %zu\n", tileset.c_str(), objects.size(), tiles);
    std::printf("latitude = %s\nlongitude = %s\nheight = %s\nheading = %s\nplaced_by = %s\n",
                format_number(origin.latitude_degrees).c_str(),
                format_number(origin.longitude_degrees).c_str(), format_number(origin.height).c_str(),
                format_number(origin.heading_degrees).c_str(), placement.by.c_str());
    return 0;
}

}  // namespace

Subcommand tiles_subcommand() {
    Subcommand tiles{
        {"tiles",
         "MODEL|PARAMS.txt",
         "Write a 3D Tiles 1.1 tileset: every child of the model's root (a city's buildings and "
         "streets) and the root's own geometry (the whole model where all of it is on the root) "
         "an object whose levels are a chain of tiles, coarsest first, refined by REPLACE down "
         "to the original; glb content, boxes from boxlod's boxes, geometric errors in metres "
         "that make clients switch levels where a chain does (16 pixels at the level's switch "
         "distance, --switch-error); OUTDIR/tileset.json and OUTDIR/object_K_L<c>.glb.",
         {
             {"output", "OUTDIR", "folder for the tileset (required)", {}, "", 'o'},
             {"latitude", "DEG",
              "where the model's origin lies on the WGS84 ellipsoid, with --longitude (by default where a "
              "city file's reference system places it (PROJ), else KIT, Karlsruhe)",
              latitude_range, format_number(Geodetic{}.latitude_degrees)},
             {"longitude", "DEG", "its longitude", longitude_range,
              format_number(Geodetic{}.longitude_degrees)},
             {"reference-system",
              "CRS",
              "the model's coordinate reference system as PROJ names it (EPSG:7415), for a city file "
              "that names none or another: where its coordinates lie on the Earth",
              {},
              ""},
             {"height", "M",
              "its height above the ellipsoid (by default a city file's own, a compound system's with "
              "EGM96's geoid added, else 0)",
              height_range, format_number(Geodetic{}.height)},
             keep_hierarchy_option(),
             switch_error_option(),
             threads_option(),
         },
         1,
         1},
        run_tiles};
    std::vector<Option> lod = lod_options();  // but --level: tiles writes every level of each object
    std::erase_if(lod, [](const Option& option) { return option.name == "level"; });
    tiles.command.options.insert(tiles.command.options.begin() + 1, lod.begin(), lod.end());
    return tiles;
}

}  // namespace boxlod
