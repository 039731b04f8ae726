#include "toolkit/formats/model_io.h"

#include "base/input_error.h"
#include "base/input_file.h"
#include "toolkit/formats/assimp_io.h"
#include "toolkit/formats/cityjson_import.h"
#include "toolkit/formats/gltf_io.h"

namespace boxlod {

Model load_model(const std::string& path, const ReadOptions& options) {
    check_input_file(path, "model file");
    std::string extension = lowercase_extension(path);
    if (extension == ".gltf" || extension == ".glb") return import_gltf(path, options.chain_level);
    if (options.chain_level > 0) throw_input_error(path, "", "only a glTF LoD chain (build --chain) has levels to choose");
    if (extension == ".json" || extension == ".jsonl") return import_cityjson(path, options.city_lod);
    static const char* assimp_formats[] = {".fbx", ".obj", ".dae", ".ply", ".off", ".3ds", ".ifc", ".stl", ".x3d",
                                           ".blend", ".ase", ".lwo", ".ms3d", ".x", ".3mf", ".ac"};
    for (const char* known : assimp_formats)
        if (extension == known) return import_with_assimp(path);
    throw_input_error(path, "", "unknown model format '" + extension +
                                    "' (known: .gltf .glb .json .jsonl (CityJSON) .fbx .obj .dae .ply .off .3ds .ifc .stl .x3d .blend .ase .lwo .ms3d .x .3mf .ac)");
}

void save_model(const Model& model, const std::string& path) {
    std::string extension = lowercase_extension(path);
    if (extension != ".gltf" && extension != ".glb")
        throw_input_error(path, "", "models are saved as .gltf or .glb");
    export_gltf(model, path);
}

}  // namespace boxlod
