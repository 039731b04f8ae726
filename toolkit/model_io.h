// Loading and saving models by file extension: glTF natively, everything
// else assimp reads.
#pragma once
#include "toolkit/model.h"

#include <string>

namespace boxlod {

Model load_model(const std::string& path);
void save_model(const Model& model, const std::string& path);  // .gltf or .glb

}  // namespace boxlod
