// Loading and saving models by file extension: glTF and CityJSON natively,
// everything else assimp reads.
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
