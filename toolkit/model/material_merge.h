// Materials as a client wants them: an importer's copies of one material
// (assimp gives each shape of an IFC file its own) merged, and materials that no
// primitive draws (those of parts a simplification removed) dropped.
#pragma once
#include "toolkit/model/model.h"

namespace boxlod {

// Keeps the first of materials equal in every field, the name too, and only
// materials some primitive draws, in their order; renumbers the primitives'
// materials. Textures stay as they are. Returns how many were removed.
std::size_t merge_materials(Model& model);

}  // namespace boxlod
