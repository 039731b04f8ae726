// A level of detail as the builder makes it (lod_builder.h) and a chain hands
// it out (chain/chain.h), and the time spent making levels: what the
// commands, the sweep and the library see of a level, without the session
// that made it (lod_session.h, lod/'s own).
#pragma once
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "toolkit/lod/cut/cut.h"
#include "toolkit/lod/pages/atlas.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/model.h"

#include <cstdint>
#include <memory>

namespace boxlod {

struct LodTimes {  // seconds, for the time split in docs/performance.md
    double boxes = 0, levels = 0, bake = 0, pack = 0, mesh = 0;
    double preview = 0, write = 0;  // rendering NAME.preview.png; writing the files
};

struct Lod {
    int current_level = 0;
    // is_lod and lod_params set; the pages' textures (lod_page) and materials come first.
    Model model;
    Cut cut;
    Atlas atlas;  // no pages in untextured mode (no baking)
    std::uint64_t face_texels =
        0;                   // the packed faces' own texels (cropped), without gutters and free page space
    double depth_error = 0;  // the proxy error of the cut: e(n) summed over its boxes (error_greedy.h), m^3
    double measured_error =
        0;  // hybrid: its proxies' measured errors summed (hybrid_cut_error), sizing-view pixels
    CostParts
        cost;  // of `model` (docs/design.md: Cost), computed once for the statistics and whoever draws it
    KeyValues statistics;  // docs/design.md: Statistics
    // Its pages' bytes while it (or a copy) lives, counted by every memory check (level_faces.h); a
    // model moved out of it and kept is no longer counted.
    std::shared_ptr<const MemoryHold> pages_held;
};

}  // namespace boxlod
