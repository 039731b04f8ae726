// IFC (2x, 2x3, 4, 4x3) read with web-ifc (npm, MPL-2.0; pinned
// in web_ifc_version.txt, installed by `make demo` and `make test` into the
// npm cache folder), run by node in a child process: the spatial structure as
// the node tree (Project > Site > Building > Storey > element > its parts,
// from IfcRelAggregates and IfcRelContainedInSpatialStructure), each element's
// colour and transparency from its styles, its IFC type as the node's rule and
// its GlobalId as the node's source id; nodes that draw nothing, themselves
// or below them, left out (docs/design.md: Scene model). The first read keeps V8's
// compiled code of web-ifc beside the module, for the next reads to load rather than compile.
#pragma once
#include "toolkit/model/model.h"

#include <string>

namespace boxlod {

// The web-ifc module folder: $BOXLOD_WEB_IFC, else web-ifc-VERSION in the npm
// cache folder ($BOXLOD_NPM_CACHE, else $XDG_CACHE_HOME or ~/.cache, /boxlod/npm);
// "" when it is not there.
std::string web_ifc_module();

Model import_ifc_with_web_ifc(const std::string& path);

}  // namespace boxlod
