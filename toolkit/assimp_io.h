// Every other format users have (FBX, OBJ, DAE, PLY, OFF, 3DS, IFC 2x3, ...),
// read with assimp, hierarchy kept where the format has one.
#pragma once
#include "toolkit/model.h"

#include <string>

namespace boxlod {

Model import_with_assimp(const std::string& path);

}  // namespace boxlod
