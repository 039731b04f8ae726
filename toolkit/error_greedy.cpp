#include "toolkit/error_greedy.h"

#include "toolkit/cost.h"
#include "toolkit/kept_subtrees.h"

#include <cmath>
#include <set>
#include <tuple>

namespace boxlod {

std::vector<double> box_depth_errors(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes) {
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
        for (const Primitive& p : model.nodes[n].primitives) own_bytes[n] += double(primitive_mesh_bytes(p, model));
    }
    // What opening n buys and costs: its box gives way to its own geometry and its children's boxes.
    auto change = [&](int n) {
        double gain = errors[std::size_t(n)], cost = own_bytes[std::size_t(n)] - box_bytes[std::size_t(n)];
        for (int child : model.nodes[std::size_t(n)].children)
            if (boxes[std::size_t(child)]) gain -= errors[std::size_t(child)], cost += box_bytes[std::size_t(child)];
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

LevelValues error_greedy_levels(const Model& model, const std::vector<std::optional<OrientedBox>>& boxes,
                                int wanted_levels, const TextureSizing& sizing, bool textured) {
    const GreedyOpening opening = greedy_opening(model, boxes, sizing, textured);
    LevelValues values;
    values.obtained_levels = wanted_levels;
    values.level.assign(model.nodes.size(), 0);
    if (opening.order.empty()) return values;
    const double root = std::max(opening.bytes.front(), 1.0), original = std::max(opening.bytes.back(), 1.0);
    // prefix[c]: openings kept at level c, never more at a coarser level.
    std::vector<std::size_t> prefix(std::size_t(wanted_levels) + 1, 0);
    for (int c = wanted_levels; c >= 1; --c) {
        const double t = double(c) / wanted_levels;
        const double budget = std::exp((1 - t) * std::log(original) + t * std::log(root));
        std::size_t k = 0;
        for (std::size_t j = 0; j < opening.bytes.size(); ++j)
            if (opening.bytes[j] <= budget * (1 + 1e-12)) k = j;
        prefix[std::size_t(c)] = c == wanted_levels ? k : std::max(k, prefix[std::size_t(c) + 1]);
    }
    for (std::size_t step = 0; step < opening.order.size(); ++step)
        for (int c = wanted_levels; c >= 1; --c)
            if (prefix[std::size_t(c)] > step) {  // opened at step + 1 <= prefix: open at level c
                values.level[std::size_t(opening.order[step])] = c;
                break;
            }
    return values;
}

}  // namespace boxlod
