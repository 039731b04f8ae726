// Every other format users have (FBX, OBJ, DAE, PLY, OFF, 3DS, ...), read
// with assimp, hierarchy kept where the format has one; it reads IFC 2x3
// too, which boxlod reads by web-ifc (assimp's reading is the peer of its
// benchmark and tests).
#pragma once
#include "toolkit/model/model.h"

#include <string>

namespace boxlod {

// assimp's importers are third-party code reading untrusted bytes: they run
// in a child process under memory and time limits (base/child_process.h),
// which hands the scene back (toolkit/formats/model_bytes.h); a crash there is one
// line naming the file.
Model import_with_assimp(const std::string& path);
// The same read in this process (what the child runs).
Model import_with_assimp_in_process(const std::string& path);

}  // namespace boxlod
