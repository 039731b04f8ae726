// Loading and saving models by file extension: glTF and CityJSON natively,
// IFC with web-ifc (toolkit/formats/ifc_io.h), everything else as assimp
// reads it.
#pragma once
#include "toolkit/model/model.h"

#include <string>
#include <vector>

namespace boxlod {

// What a reader is asked for beyond the file.
struct ReadOptions {
    int chain_level = 0;  // > 0: that level of a glTF LoD chain (toolkit/formats/gltf_io.h)
    std::string
        city_lod;  // CityJSON: the LoD read ("": each object's finest; toolkit/formats/cityjson_import.h)
};

// `path` may name one object of a city file, FILE#OBJECT (a CityJSON
// Building's id, a node name of a generated city's root's children): that
// object alone (toolkit/model/model_subtree.h: object_model), at the file's
// origin, when FILE exists and the whole path does not.
Model load_model(const std::string& path, const ReadOptions& options = {});

// The file load_model reads for `path`: FILE of FILE#OBJECT, else path
// (what an output must not replace).
std::string model_file_of(const std::string& path);

// The names of a city file's objects, for FILE#OBJECT (in the file's order).
std::vector<std::string> object_names(const Model& city);
void save_model(const Model& model, const std::string& path);  // .gltf or .glb

}  // namespace boxlod
