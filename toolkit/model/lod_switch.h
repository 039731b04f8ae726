// Where an engine switches to a level of a chain, in the terms each engine
// takes (docs/cost.md: Switching levels); toolkit/lod/chain/switch_measures.h
// computes them from a level's sizing.
#pragma once

namespace boxlod {

constexpr double switch_screen_aspect = 16.0 / 9.0;  // the screen the measures assume

struct LodSwitch {
    double distance = 0;
    // MSFT_lod's MSFT_screencoverage: the sphere's projected area over the
    // screen's, pi r^2 / (aspect H^2) (as Babylon.js Mesh.getLOD reads it).
    double screen_coverage = 0;
    double unity_relative_height = 0;  // Unity LODGroup screenRelativeTransitionHeight: s / H
    double unreal_screen_size = 0;  // Unreal ComputeBoundsScreenSize: the sphere's diameter over H, 2 r / H
};

}  // namespace boxlod
