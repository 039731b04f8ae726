// How far the surface a level draws lies from the original's: the geometric
// error 3D Tiles asks of a tile, in metres (3D Tiles 1.1: Geometric error;
// chain/switch_measures.h). Measured, not guessed: each model is rendered orthographically
// along both directions of each axis of a frame (the object's box), at most
// `max_side` pixels a side, and the deviation is the largest difference in
// depth over the pixels both renders cover. A pixel that only one covers is
// not counted; the view from the other side sees what lies there.
#pragma once
#include "toolkit/model/model.h"

#include <vector>

namespace boxlod {

// A model's depth seen along the six directions of a frame.
struct SurfaceViews {
    std::vector<std::vector<float>>
        depth;  // per direction (+a0, -a0, +a1, ...): metres from the camera; +inf uncovered
};

// Masked materials (baked box faces) are drawn as their alpha test draws them.
SurfaceViews surface_views(const Model& model, const OrientedBox& frame, int max_side = 128, int threads = 1);

// The largest depth difference of two models' views of the same frame, metres.
double surface_deviation(const SurfaceViews& original, const SurfaceViews& level);

}  // namespace boxlod
