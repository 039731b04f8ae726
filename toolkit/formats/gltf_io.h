// glTF 2.0 (.gltf, .glb) import and export, with tinygltf.
// Node transforms are applied (in double, relative to a local origin for a
// model more than 10 km from the file's) and shared meshes expanded on import;
// scopes, rules and the LoD mark travel in `extras.boxlod` (docs/design.md: Scene model).
#pragma once
#include "toolkit/model/lod_switch.h"
#include "toolkit/model/model.h"

#include <string>
#include <string_view>
#include <vector>

namespace boxlod {

// `chain_level` K > 0 reads level K of an LoD chain (build --chain) instead
// of its scene: the root that the scene's root lists K-th in MSFT_lod.ids,
// what an MSFT_lod client draws at that level.
Model import_gltf(const std::string& path, int chain_level = 0);
// The same from the file's bytes; `path` names it in errors and places the files it refers to.
Model import_gltf_bytes(std::string_view bytes, bool binary, const std::string& path, int chain_level = 0);

// Writes .gltf (+ .bin and one PNG per texture beside it) or a single .glb,
// chosen by the extension; every file atomically. Geometry is stored in
// world space, so exported nodes have no transforms.
void export_gltf(const Model& model, const std::string& path, int threads = 0);
// The same model as the bytes of a .glb, in memory (import_gltf_bytes reads it back exactly).
std::string gltf_binary(const Model& model, int threads = 0);

// Several levels of detail in one file, finest first: only levels[0] is in the
// scene (what a client without the extension draws); its root's MSFT_lod
// extension lists the others' roots. `switches` holds where levels 1..N take
// over: extras.MSFT_screencoverage gets their screen coverages (level k is
// drawn while the model covers at least value k of the screen; the coarsest,
// 0: always) and extras.boxlod.switch_distances their distances, which
// viewers switch by (clients/chain_three.html). Equal textures and geometry
// are stored once (docs/cost.md: Switching levels).
void export_gltf_lods(const std::vector<const Model*>& levels, const std::vector<LodSwitch>& switches,
                      const std::string& path, int threads = 0);

}  // namespace boxlod
