// The far end of the simplification baseline (docs/sweeps.md): the whole
// model as one untextured box in its average colour. The LoD builder's top
// level is the same box but with baked textures; this is what classic
// simplification would end with.
#pragma once
#include "toolkit/model/model.h"

namespace boxlod {

// The root's minimal box (docs/design.md: Boxes; the box the LoD's top level uses)
// as 6 quads with outward normals, one material: the area-weighted mean of
// the materials' linear colours, each times its base texture's mean colour.
Model single_box_model(const Model& model, int threads = 0);

}  // namespace boxlod
