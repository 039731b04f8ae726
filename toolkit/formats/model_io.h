// Loading and saving models by file extension: glTF natively, everything
// else assimp reads.
#pragma once
#include "toolkit/model/model.h"

#include <string>

namespace boxlod {

// `chain_level` > 0: that level of a glTF LoD chain (toolkit/formats/gltf_io.h).
Model load_model(const std::string& path, int chain_level = 0);
void save_model(const Model& model, const std::string& path);  // .gltf or .glb

}  // namespace boxlod
