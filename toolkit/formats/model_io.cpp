#include "toolkit/formats/model_io.h"

#include "base/input_error.h"
#include "base/input_file.h"
#include "toolkit/formats/assimp_io.h"
#include "toolkit/formats/cityjson_import.h"
#include "toolkit/formats/gltf_io.h"
#include "toolkit/formats/ifc_io.h"
#include "toolkit/model/model_subtree.h"

#include <filesystem>

namespace boxlod {

namespace {

namespace fs = std::filesystem;

// The file itself, by its extension.
Model load_file(const std::string& path, const ReadOptions& options) {
    check_input_file(path, "model file");
    std::string extension = lowercase_extension(path);
    if (extension == ".gltf" || extension == ".glb") return import_gltf(path, options.chain_level);
    if (options.chain_level > 0)
        throw_input_error(path, "", "only a glTF LoD chain (build --chain) has levels to choose");
    if (extension == ".json" || extension == ".jsonl") return import_cityjson(path, options.city_lod);
    if (extension == ".ifc")
        return import_ifc_with_web_ifc(path);  // every schema (docs/design.md: Scene model)
    static const char* assimp_formats[] = {".fbx",   ".obj", ".dae", ".ply",  ".off", ".3ds", ".stl", ".x3d",
                                           ".blend", ".ase", ".lwo", ".ms3d", ".x",   ".3mf", ".ac"};
    for (const char* known : assimp_formats)
        if (extension == known) return import_with_assimp(path);
    throw_input_error(path, "",
                      "unknown model format '" + extension +
                          "' (known: .gltf .glb .json .jsonl (CityJSON) .fbx .obj .dae .ply .off .3ds .ifc "
                          ".stl .x3d .blend .ase .lwo .ms3d .x .3mf .ac)");
}

}  // namespace

std::vector<std::string> object_names(const Model& city) {
    std::vector<std::string> names;
    for (int node : object_nodes(city))
        names.push_back(node < 0 ? city.nodes[0].name : city.nodes[std::size_t(node)].name);
    return names;
}

std::string model_file_of(const std::string& path) {
    std::error_code error;
    const std::size_t hash = path.rfind('#');
    if (hash == std::string::npos || fs::exists(path, error) ||
        !fs::is_regular_file(path.substr(0, hash), error))
        return path;
    return path.substr(0, hash);
}

Model load_model(const std::string& path, const ReadOptions& options) {
    const std::string file = model_file_of(path);
    if (file == path) return load_file(path, options);
    const std::string object = path.substr(file.size() + 1);
    const Model city = load_file(file, options);
    const std::vector<int> nodes = object_nodes(city);
    const std::vector<std::string> names = object_names(city);
    for (std::size_t k = 0; k < nodes.size(); ++k)
        if (names[k] == object) {
            Model one = object_model(city, nodes[k]);
            one.source = path;
            return one;
        }
    throw_input_error(file, "",
                      "no object named '" + object + "' (" + std::to_string(names.size()) + " objects: " +
                          (names.empty() ? std::string("none") : names.front() + ", ...") + ")");
}

void save_model(const Model& model, const std::string& path) {
    std::string extension = lowercase_extension(path);
    if (extension != ".gltf" && extension != ".glb")
        throw_input_error(path, "", "models are saved as .gltf or .glb");
    export_gltf(model, path);
}

}  // namespace boxlod
