// Selection under a face budget: when the levels the strategy chose draw more
// faces than the budget allows, objects are coarsened one level at a time, the
// least important first, until the faces fit. This is how strategies are
// compared at equal budgets.
#pragma once
#include "toolkit/selection/lod_selection.h"

#include <cstddef>
#include <vector>

namespace boxlod {

// How much an object matters in this view, by the strategy's own value, larger =
// more important: the pixel count, screen ratio or projected diagonal itself, the
// negated distance or pixel footprint (which grow as the object matters less).
double selection_importance(const Strategy& strategy, const SelectionObject& object,
                            const SelectionView& view);

// Faces drawn: `fixed_faces` (drawn whatever the levels, e.g. streets) plus each
// object's faces at its level.
std::size_t faces_drawn(const std::vector<SelectionObject>& objects, const std::vector<int>& levels,
                        std::size_t fixed_faces = 0);

// Coarsens `levels` (one per object, each in 0..N) while faces_drawn exceeds `budget`:
// the object of least importance (ties: the later object) goes one level coarser until
// it reaches N, then the next. Returns faces_drawn of the result, which is within the
// budget unless every object is at N and still exceeds it.
std::size_t fit_face_budget(const std::vector<SelectionObject>& objects,
                            const std::vector<double>& importance, std::size_t budget,
                            std::vector<int>& levels, std::size_t fixed_faces = 0);

}  // namespace boxlod
