#include "toolkit/lod/hybrid/hybrid_order.h"

#include "toolkit/lod/cut/kept_subtrees.h"
#include "toolkit/lod/hybrid/paid_textures.h"
#include "toolkit/model/vertex_layout.h"

#include <cmath>
#include <optional>
#include <set>
#include <tuple>

namespace boxlod {

std::vector<int> proxy_textures(const PaidTextures& paid, const Proxy& proxy) {
    return proxy.kind == ProxyKind::simplified ? textures_of(paid, proxy.primitives) : std::vector<int>{};
}

namespace {

// The greedy order (docs/design.md: The hybrid level mode), within a byte
// budget: a change that would exceed it gives way to the node's best change
// that fits, if any, so a level fills its budget where the unbounded order
// takes one large step past it. A change's bytes count textures as a level
// pays for them (paid_textures.h), so they change as other parts are drawn:
// a queued change whose bytes went stale is weighed again when it comes up.
class Planner {
public:
    Planner(const Model& model, const std::vector<std::vector<Proxy>>& proxies, double budget)
        : model_(model),
          proxies_(proxies),
          budget_(budget),
          state_(model.nodes.size(), -1),
          paid_(paid_textures(model)),
          drawn_(paid_) {
        subtree_bytes_.assign(model.nodes.size(), 0);
        own_bytes_.assign(model.nodes.size(), 0);
        own_textures_ = node_textures(model, paid_);
        subtree_textures_ = subtree_textures(model, paid_);
        proxy_textures_.resize(model.nodes.size());
        const std::vector<std::uint64_t> subtree = subtree_mesh_bytes(model);
        for (std::size_t n = 0; n < model.nodes.size(); ++n) {
            subtree_bytes_[n] = double(subtree[n]);
            own_bytes_[n] = double(mesh_bytes(model.nodes[n].primitives, model));
            for (const Proxy& proxy : proxies[n]) proxy_textures_[n].push_back(proxy_textures(paid_, proxy));
            if (!proxies[n].empty()) state_[n] = 0;  // the cheapest, until changed
        }
    }

    // From `start` (each node in it reached from the root down), if given, then greedily.
    void run(const std::vector<int>* start, std::vector<HybridStep>& steps, std::vector<double>& bytes,
             std::vector<double>& error) {
        bytes.push_back(drawn_bytes(0) + drawn_.apply({}, {&drawn_textures(0)}));
        error.push_back(drawn_error(0));
        if (state_[0] < 0) return;  // the root has no proxy: only the original
        if (start) reach(*start, steps, bytes, error);
        for (std::vector<int> stack{0}; !stack.empty();) {  // the parts drawn now, each its best change
            const int n = stack.back();
            stack.pop_back();
            if (state_[std::size_t(n)] >= 0) {
                consider(n, budget_ - bytes.back());
                continue;
            }
            if (!proxies_[std::size_t(n)].empty())
                for (int child : model_.nodes[std::size_t(n)].children) stack.push_back(child);
        }
        while (!frontier_.empty()) {
            const Move move = std::get<3>(*frontier_.begin());
            frontier_.erase(frontier_.begin());
            if (weigh(move.node, move.proxy).cost != move.cost ||
                bytes.back() + move.cost > budget_ * (1 + 1e-12)) {
                consider(move.node, budget_ - bytes.back());  // its best now, that fits, if any
                continue;
            }
            take(move, steps, bytes, error);
            if (move.proxy >= 0) {
                consider(move.node, budget_ - bytes.back());
                continue;
            }
            for (int child : model_.nodes[std::size_t(move.node)].children)
                if (state_[std::size_t(child)] >= 0) consider(child, budget_ - bytes.back());
        }
    }

private:
    struct Move {
        int node = 0, proxy = -1;
        double gain = 0, cost = 0;
    };
    // Best first: changes that save bytes and lose nothing, then the largest
    // gain per byte, then (so that the plan reaches the original) openings that
    // gain nothing yet, cheapest first; ties to the lower node index.
    using Key = std::tuple<int, double, int, Move>;
    struct KeyOrder {
        bool operator()(const Key& a, const Key& b) const {
            return std::tie(std::get<0>(a), std::get<1>(a), std::get<2>(a)) <
                   std::tie(std::get<0>(b), std::get<1>(b), std::get<2>(b));
        }
    };

    // Mesh bytes, textures and error of node n's sub-tree as drawn when n is reached in its current state.
    double drawn_bytes(int n) const {
        const int s = state_[std::size_t(n)];
        return s >= 0 ? proxies_[std::size_t(n)][std::size_t(s)].bytes : subtree_bytes_[std::size_t(n)];
    }
    const std::vector<int>& drawn_textures(int n) const {
        const int s = state_[std::size_t(n)];
        return s >= 0 ? proxy_textures_[std::size_t(n)][std::size_t(s)] : subtree_textures_[std::size_t(n)];
    }
    double drawn_error(int n) const {
        const int s = state_[std::size_t(n)];
        return s >= 0 ? proxies_[std::size_t(n)][std::size_t(s)].error : 0;
    }

    // The textures of what node n draws after changing to `proxy` (-1: opened).
    std::vector<const std::vector<int>*> added_textures(int n, int proxy) const {
        if (proxy >= 0) return {&proxy_textures_[std::size_t(n)][std::size_t(proxy)]};
        std::vector<const std::vector<int>*> added{&own_textures_[std::size_t(n)]};
        for (int child : model_.nodes[std::size_t(n)].children) added.push_back(&drawn_textures(child));
        return added;
    }

    // Node n changed from its current proxy to `proxy` (-1: opened, its own
    // geometry and its children as they are drawn), as the parts drawn now price it.
    Move weigh(int n, int proxy) {
        const Proxy& now = proxies_[std::size_t(n)][std::size_t(state_[std::size_t(n)])];
        Move move{n, proxy, now.error, -now.bytes};
        if (proxy >= 0) {
            move.gain -= proxies_[std::size_t(n)][std::size_t(proxy)].error;
            move.cost += proxies_[std::size_t(n)][std::size_t(proxy)].bytes;
        } else {
            move.cost += own_bytes_[std::size_t(n)];
            for (int child : model_.nodes[std::size_t(n)].children) {
                move.gain -= drawn_error(child);
                move.cost += drawn_bytes(child);
            }
        }
        move.cost += drawn_.change(drawn_textures(n), added_textures(n, proxy));
        return move;
    }

    void take(const Move& move, std::vector<HybridStep>& steps, std::vector<double>& bytes,
              std::vector<double>& error) {
        steps.push_back({move.node, move.proxy});
        bytes.push_back(bytes.back() + move.cost);
        error.push_back(error.back() - move.gain);
        drawn_.apply(drawn_textures(move.node), added_textures(move.node, move.proxy));
        state_[std::size_t(move.node)] = move.proxy;
    }

    // The steps from the root's cheapest proxy to `target`, parents before their children.
    void reach(const std::vector<int>& target, std::vector<HybridStep>& steps, std::vector<double>& bytes,
               std::vector<double>& error) {
        for (std::vector<int> stack{0}; !stack.empty();) {
            const int n = stack.back();
            stack.pop_back();
            const int wanted = target[std::size_t(n)];
            if (proxies_[std::size_t(n)].empty() || wanted == state_[std::size_t(n)]) continue;
            take(weigh(n, wanted), steps, bytes, error);
            if (wanted < 0)
                for (int child : model_.nodes[std::size_t(n)].children) stack.push_back(child);
        }
    }

    static Key key(const Move& m) {
        if (m.gain >= 0 && m.cost <= 0) return {0, -m.gain, m.node, m};
        if (m.gain > 0) return {1, -m.gain / m.cost, m.node, m};
        return {2, m.cost, m.node, m};
    }

    // Puts node n's best change adding at most `room` bytes into the frontier.
    void consider(int n, double room) {
        std::optional<Key> best;
        auto offer = [&](const Move& m) {
            if (m.cost <= room * (1 + 1e-12) + 1e-9 && (!best || KeyOrder{}(key(m), *best))) best = key(m);
        };
        offer(weigh(n, -1));
        for (std::size_t j = std::size_t(state_[std::size_t(n)]) + 1; j < proxies_[std::size_t(n)].size();
             ++j)
            offer(weigh(n, int(j)));
        if (best) frontier_.insert(*best);
    }

    const Model& model_;
    const std::vector<std::vector<Proxy>>& proxies_;
    double budget_;
    std::vector<int> state_;
    std::vector<double> subtree_bytes_, own_bytes_;
    PaidTextures paid_;
    DrawnTextures drawn_;
    std::vector<std::vector<int>> own_textures_, subtree_textures_;
    std::vector<std::vector<std::vector<int>>> proxy_textures_;  // per node and proxy
    std::set<Key, KeyOrder> frontier_;
};

}  // namespace

void order_within(const Model& model, const std::vector<std::vector<Proxy>>& proxies, double budget,
                  std::vector<HybridStep>& steps, std::vector<double>& bytes, std::vector<double>& error,
                  const std::vector<int>* start) {
    Planner(model, proxies, budget).run(start, steps, bytes, error);
}

namespace {

// lambda's 18 decades to a hundred-millionth of one
constexpr int pruning_bisections = 32;

// Each node's choices priced alone: its proxies' bytes with the textures each
// samples, and (opened) its own geometry's and textures, or (without proxies)
// its whole sub-tree's; children after their parents in `order`.
struct PruningCosts {
    std::vector<std::vector<double>> proxy_bytes;
    std::vector<double> open_bytes, whole_bytes;
    std::vector<int> order;
};

PruningCosts pruning_costs(const Model& model, const std::vector<std::vector<Proxy>>& proxies) {
    const PaidTextures paid = paid_textures(model);
    const std::vector<std::vector<int>> own = node_textures(model, paid),
                                        whole = subtree_textures(model, paid);
    const std::vector<std::uint64_t> subtree = subtree_mesh_bytes(model);
    PruningCosts costs;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        costs.proxy_bytes.emplace_back();
        for (const Proxy& proxy : proxies[n])
            costs.proxy_bytes.back().push_back(proxy.bytes + bytes_of(paid, proxy_textures(paid, proxy)));
        costs.open_bytes.push_back(double(mesh_bytes(model.nodes[n].primitives, model)) +
                                   bytes_of(paid, own[n]));
        costs.whole_bytes.push_back(double(subtree[n]) + bytes_of(paid, whole[n]));
    }
    for (std::vector<int> stack{0}; !stack.empty();) {
        const int n = stack.back();
        stack.pop_back();
        costs.order.push_back(n);
        for (int child : model.nodes[std::size_t(n)].children) stack.push_back(child);
    }
    return costs;
}

// The state minimizing error + lambda x bytes, and its bytes as priced alone.
std::pair<std::vector<int>, double> pruned_state(const std::vector<std::vector<Proxy>>& proxies,
                                                 const Model& model, const PruningCosts& costs,
                                                 double lambda) {
    const std::size_t count = model.nodes.size();
    std::vector<double> value(count), bytes(count);
    std::vector<int> choice(count, -1);
    for (auto it = costs.order.rbegin(); it != costs.order.rend(); ++it) {  // children first
        const auto n = std::size_t(*it);
        if (proxies[n].empty()) {  // drawn whole where reached
            bytes[n] = costs.whole_bytes[n];
            value[n] = lambda * bytes[n];
            continue;
        }
        bytes[n] = costs.open_bytes[n];
        for (int child : model.nodes[n].children) bytes[n] += bytes[std::size_t(child)];
        value[n] = lambda * costs.open_bytes[n];
        for (int child : model.nodes[n].children) value[n] += value[std::size_t(child)];
        for (std::size_t p = 0; p < proxies[n].size(); ++p) {
            const double v = proxies[n][p].error + lambda * costs.proxy_bytes[n][p];
            if (v < value[n]) {
                value[n] = v;
                bytes[n] = costs.proxy_bytes[n][p];
                choice[n] = int(p);
            }
        }
    }
    std::vector<int> state(count, -1);
    for (std::size_t n = 0; n < count; ++n)
        if (!proxies[n].empty()) state[n] = 0;
    for (std::vector<int> stack{0}; !stack.empty();) {
        const auto n = std::size_t(stack.back());
        stack.pop_back();
        if (proxies[n].empty()) continue;
        state[n] = choice[n];
        if (choice[n] < 0)
            for (int child : model.nodes[n].children) stack.push_back(child);
    }
    return {state, bytes[0]};
}

}  // namespace

std::vector<int> pruned_state_within(const Model& model, const std::vector<std::vector<Proxy>>& proxies,
                                     double budget) {
    const PruningCosts costs = pruning_costs(model, proxies);
    // The least lambda whose cut fits, by bisection of its logarithm (a cut's
    // bytes fall as lambda grows): at 1e6 bytes per pixel of error no change
    // pays, at 1e-12 every one does.
    double low = 1e-12, high = 1e6;
    for (int k = 0; k < pruning_bisections; ++k) {
        const double lambda = std::sqrt(low * high);
        (pruned_state(proxies, model, costs, lambda).second <= budget ? high : low) = lambda;
    }
    return pruned_state(proxies, model, costs, high).first;
}

}  // namespace boxlod
