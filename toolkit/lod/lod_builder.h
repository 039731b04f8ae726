// Building an LoD (the manual's CGA section): boxes and level values once per
// model; per current level the cut, baking of the boxes not baked before,
// atlas packing and the LoD mesh (kept original nodes + textured box quads).
#pragma once
#include "base/key_values.h"
#include "toolkit/lod/cut/cut.h"
#include "toolkit/lod/cut/error_greedy.h"
#include "toolkit/lod/hybrid/hybrid.h"
#include "toolkit/lod/lod.h"
#include "toolkit/lod/lod_session.h"
#include "toolkit/lod/pages/atlas.h"
#include "toolkit/lod/pages/bake.h"
#include "toolkit/lod/pages/level_pages.h"
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/lod/parameter_file.h"
#include "toolkit/model/cost.h"

#include <map>
#include <memory>

namespace boxlod {

// Throws InputError for an LoD model (boxlod does not simplify its own output) or bad parameters.
// `boxes`, when given, are the model's node_boxes for parameters.box_kind (computed once, reused).
// `measurements`, when given, are shared with the sessions of the same model at
// other distances (level mode hybrid: chain.h).
std::unique_ptr<LodSession> start_lod(const Model& model, const LodParameters& parameters, int threads,
                                      const std::vector<std::optional<OrientedBox>>* boxes = nullptr,
                                      HybridMeasurements* measurements = nullptr);

Lod build_lod(LodSession& session, int current_level, int threads);

// The whole model as one baked proxy (baked_proxy.h): `geometry` (the model
// simplified; its materials are not read) drawn with the colours and normals of the
// root's box faces baked at the session's sizing, texels `texel_scale` times
// as large (texture_sizing.h: coarser_sizing): the proxy-baked baseline
// (docs/sweeps.md), a far level as Simplygon and Unreal's HLOD make it.
// Its parameters and statistics name it level `level`. Throws InputError for
// an untextured session (a baked proxy draws pages) or a model without geometry.
Lod build_baked_model(LodSession& session, const std::vector<Primitive>& geometry, int texel_scale, int level,
                      int threads);

// Throws InputError when level c's byte budget lies below the real bytes of
// the session's coarsest cut, where build_lod would fail: a command calls it
// before it writes any level, so a refused build leaves nothing behind.
void check_budget_reachable(LodSession& session, int level, int threads);

}  // namespace boxlod
