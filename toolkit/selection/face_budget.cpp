#include "toolkit/selection/face_budget.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace boxlod {

double selection_importance(const Strategy& strategy, const SelectionObject& object,
                            const SelectionView& view) {
    double value = strategy_value(strategy, object, view);
    bool grows_coarser = std::holds_alternative<DistanceBands>(strategy) ||
                         std::holds_alternative<TexelExact>(strategy) ||
                         std::holds_alternative<MeasuredSwitch>(strategy);
    return grows_coarser ? -value : value;
}

std::size_t faces_drawn(const std::vector<SelectionObject>& objects, const std::vector<int>& levels,
                        std::size_t fixed_faces) {
    if (levels.size() != objects.size()) throw std::invalid_argument("faces_drawn: one level per object");
    std::size_t faces = fixed_faces;
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (!objects[i].levels.empty()) faces += objects[i].levels.at(std::size_t(levels[i])).faces;
    return faces;
}

std::size_t fit_face_budget(const std::vector<SelectionObject>& objects,
                            const std::vector<double>& importance, std::size_t budget,
                            std::vector<int>& levels, std::size_t fixed_faces) {
    if (importance.size() != objects.size())
        throw std::invalid_argument("fit_face_budget: one importance per object");
    std::size_t faces = faces_drawn(objects, levels, fixed_faces);
    std::vector<std::size_t> order(objects.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    // Least important first; among equals the later object (the earlier keeps its detail). NaN counts as
    // least.
    auto rank = [&](std::size_t i) { return std::isnan(importance[i]) ? -INFINITY : importance[i]; };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return rank(a) < rank(b) || (rank(a) == rank(b) && a > b);
    });
    for (std::size_t i : order) {
        const SelectionObject& object = objects[i];
        while (faces > budget && levels[i] < coarsest_level(object)) {
            faces -= object.levels[std::size_t(levels[i])].faces;
            ++levels[i];
            faces += object.levels[std::size_t(levels[i])].faces;
        }
        if (faces <= budget) break;
    }
    return faces;
}

}  // namespace boxlod
