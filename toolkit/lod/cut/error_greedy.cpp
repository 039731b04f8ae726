#include "toolkit/lod/cut/error_greedy.h"

#include "toolkit/lod/cut/kept_subtrees.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/model/cost.h"

#include <cmath>
#include <set>
#include <tuple>

namespace boxlod {

std::vector<double> box_depth_errors(const Model& model,
                                     const std::vector<std::optional<OrientedBox>>& boxes) {
    std::vector<double> errors(model.nodes.size(), 0);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (!boxes[n]) continue;
        const OrientedBox& box = *boxes[n];
        const Eigen::Matrix3d to_box = box.axes.cast<double>().transpose();
        const Eigen::Vector3d half = box.half_extents.cast<double>(), center = box.center.cast<double>();
        double error = 0;
        for (std::vector<int> pending{int(n)}; !pending.empty();) {
            const Node& node = model.nodes[std::size_t(pending.back())];
            pending.pop_back();
            pending.insert(pending.end(), node.children.begin(), node.children.end());
            for (const Primitive& p : node.primitives)
                for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
                    const Eigen::Vector3d a = p.positions[p.indices[t]].cast<double>(),
                                          b = p.positions[p.indices[t + 1]].cast<double>(),
                                          c = p.positions[p.indices[t + 2]].cast<double>();
                    const double area = (b - a).cross(c - a).norm() / 2;
                    const Eigen::Vector3d local = to_box * ((a + b + c) / 3 - center);
                    error += area * std::max(0.0, (half - local.cwiseAbs()).minCoeff());
                }
        }
        errors[n] = error;
    }
    return errors;
}

GreedyOpening greedy_opening(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                             const TextureSizing& sizing, bool textured) {
    const std::size_t count = model.nodes.size();
    const std::vector<double> errors = box_depth_errors(model, boxes);
    std::vector<double> box_bytes(count, 0), own_bytes(count, 0);
    for (std::size_t n = 0; n < count; ++n) {
        if (boxes[n]) box_bytes[n] = double(box_bytes_estimate(*boxes[n], sizing, textured));
        for (const Primitive& p : model.nodes[n].primitives)
            own_bytes[n] += double(primitive_mesh_bytes(p, model));
    }
    // What opening n buys and costs: its box gives way to its own geometry and its children's boxes.
    auto change = [&](int n) {
        double gain = errors[std::size_t(n)], cost = own_bytes[std::size_t(n)] - box_bytes[std::size_t(n)];
        for (int child : model.nodes[std::size_t(n)].children)
            if (boxes[std::size_t(child)]) {
                gain -= errors[std::size_t(child)];
                cost += box_bytes[std::size_t(child)];
            }
        return std::pair{gain, cost};
    };
    // Best first: openings that save bytes, then the largest gain per byte; ties to the lower index.
    using Key = std::tuple<bool, double, int>;  // (costs bytes, -gain per byte, node)
    auto key = [&](int n) {
        auto [gain, cost] = change(n);
        return cost <= 0 ? Key{false, -gain, n} : Key{true, -gain / cost, n};
    };
    GreedyOpening opening;
    if (!boxes[0]) return opening;
    opening.bytes.push_back(box_bytes[0]);
    opening.error.push_back(errors[0]);
    std::set<Key> frontier{key(0)};
    while (!frontier.empty()) {
        const int n = std::get<2>(*frontier.begin());
        frontier.erase(frontier.begin());
        auto [gain, cost] = change(n);
        opening.order.push_back(n);
        opening.bytes.push_back(opening.bytes.back() + cost);
        opening.error.push_back(opening.error.back() - gain);
        for (int child : model.nodes[std::size_t(n)].children)
            if (boxes[std::size_t(child)]) frontier.insert(key(child));
    }
    return opening;
}

std::vector<std::size_t> greedy_prefixes(const GreedyOpening& opening, const std::vector<double>& budgets) {
    const std::size_t levels = budgets.size();
    std::vector<std::size_t> prefix(levels + 1, opening.order.size());
    if (opening.order.empty()) return prefix;
    for (std::size_t c = levels; c >= 1; --c) {  // never fewer openings than a coarser level
        const std::size_t k = longest_prefix_within(opening.bytes, budgets[c - 1]);
        prefix[c] = c == levels ? k : std::max(k, prefix[c + 1]);
    }
    return prefix;
}

std::vector<int> opened_levels(const Model& model, const GreedyOpening& opening,
                               const std::vector<std::size_t>& prefixes) {
    std::vector<int> level(model.nodes.size(), 0);
    for (std::size_t step = 0; step < opening.order.size(); ++step)
        for (std::size_t c = prefixes.size() - 1; c >= 1; --c)
            if (prefixes[c] > step) {  // opened at step + 1 <= prefix: open at level c
                level[std::size_t(opening.order[step])] = int(c);
                break;
            }
    return level;
}

LevelValues error_greedy_levels(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                                int wanted_levels, const TextureSizing& sizing, bool textured) {
    const GreedyOpening opening = greedy_opening(model, boxes, sizing, textured);
    LevelValues values;
    values.obtained_levels = wanted_levels;
    values.level.assign(model.nodes.size(), 0);
    if (opening.order.empty()) return values;
    values.level = opened_levels(
        model, opening,
        greedy_prefixes(opening,
                        geometric_budgets(opening.bytes.front(), opening.bytes.back(), wanted_levels)));
    return values;
}

}  // namespace boxlod
