// Loading and saving models by file extension: glTF and CityJSON natively,
// IFC 4 and 4x3 with web-ifc (toolkit/formats/ifc_io.h), everything else
// (IFC 2x3 too) as assimp reads it.
#pragma once
#include "toolkit/model/model.h"

#include <string>

namespace boxlod {

// What a reader is asked for beyond the file.
struct ReadOptions {
    int chain_level = 0;   // > 0: that level of a glTF LoD chain (toolkit/formats/gltf_io.h)
    std::string city_lod;  // CityJSON: the LoD read ("": each object's finest; toolkit/formats/cityjson_import.h)
};

Model load_model(const std::string& path, const ReadOptions& options = {});
void save_model(const Model& model, const std::string& path);  // .gltf or .glb

}  // namespace boxlod
