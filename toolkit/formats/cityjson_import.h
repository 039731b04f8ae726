// CityJSON 1.1 and 2.0 (.city.json, .json) and CityJSONSeq (.jsonl), read
// natively (docs/design.md: Files; cityjson.org/specs). The node tree is the
// file's: a node per CityObject under its parent (Building > BuildingPart),
// named by its id, its type as the node's rule; under an object, a node per
// semantic surface (WallSurface, RoofSurface, ...; a Window or Door under the
// surface it sits in) holding the polygons that name it. Polygons with holes
// are triangulated (toolkit/cgal/polygon_triangulation.h); materials and
// textures come from `appearance`, surfaces without either are drawn in their
// semantic type's colour. The model is moved to a local origin (Model::origin)
// so that far-away coordinates keep their precision in float; z-up becomes y-up.
#pragma once
#include "toolkit/model/model.h"

#include <string>
#include <string_view>
#include <vector>

namespace boxlod {

// Which geometry of each CityObject to read: "" for its finest, or a LoD as
// the file spells it ("1.2", "2"); objects without that LoD keep their node
// without geometry (one warning line counts them).
Model import_cityjson(const std::string& path, const std::string& lod = "");
// The same from bytes; `path` names the file in messages and places its
// texture files (CityJSONSeq when it ends in .jsonl).
Model import_cityjson_bytes(std::string_view bytes, const std::string& path, const std::string& lod = "");

// Every LoD the file's geometries have, finest first ("2.2", "1.3", "1.2" for 3DBAG).
std::vector<std::string> cityjson_lods(const std::string& path);

}  // namespace boxlod
