// Where an engine switches to a level of a chain (docs/cost.md: Switching
// levels): level c is drawn from the distance d_c its textures were sized for,
// where one texel meets one pixel, and stays until d_(c+1). The same switch in
// the terms engines take, for a model of bounding sphere radius r and largest
// extent s seen by the sizing view, whose height at distance d is
// H = 2 d tan(fovy / 2) on a 16:9 screen.
#pragma once
#include "toolkit/model/model.h"
#include "toolkit/lod/texture_sizing.h"

namespace boxlod {

constexpr double switch_screen_aspect = 16.0 / 9.0;

struct LodSwitch {
    double distance = 0;
    // MSFT_lod's MSFT_screencoverage: the sphere's projected area over the
    // screen's, pi r^2 / (aspect H^2) (as Babylon.js Mesh.getLOD reads it).
    double screen_coverage = 0;
    double unity_relative_height = 0;  // Unity LODGroup screenRelativeTransitionHeight: s / H
    double unreal_screen_size = 0;     // Unreal ComputeBoundsScreenSize: the sphere's diameter over H, 2 r / H
};

// The switch at `distance` (> 0) for a model of these bounds; view.distance is not read.
LodSwitch lod_switch(double distance, const Bounds& bounds, const TextureSizing& view);

}  // namespace boxlod
