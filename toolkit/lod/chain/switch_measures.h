// Where an engine switches to a level of a chain (docs/cost.md: Switching
// levels): level c is drawn from the distance d_c its textures were sized for,
// where one texel meets one pixel, and stays until d_(c+1). The same switch in
// the terms engines take, for a model of bounding sphere radius r and largest
// extent s seen by the sizing view, whose height at distance d is
// H = 2 d tan(fovy / 2) on a 16:9 screen; and as 3D Tiles' geometric error.
#pragma once
#include "toolkit/lod/pages/texture_sizing.h"
#include "toolkit/model/lod_switch.h"
#include "toolkit/model/model.h"

namespace boxlod {

// The switch at `distance` (> 0) for a model of these bounds; view.distance is not read.
LodSwitch lod_switch(double distance, const Bounds& bounds, const TextureSizing& view);

// A level's 3D Tiles geometricError in metres, switching in at d_c =
// `switch_distance`: the larger of its surface deviation from
// the original (surface_deviation.h, metres) and the metres that
// client_screen_space_error pixels (tileset.h) of the sizing view cover at d_c. A client
// projects it as e H / (2 d tan(fovy / 2)) pixels (3D Tiles 1.1: Geometric
// error) and refines while that exceeds its limit: where the level's lost
// depth would show as more than the limit, and at the latest, on a screen as
// tall as the view, where boxlod switches (its texels there are a pixel).
// view.distance is not read.
double level_geometric_error(double switch_distance, const TextureSizing& view, double surface_deviation);

}  // namespace boxlod
