#include "toolkit/lod/hybrid/hybrid_order.h"

#include "toolkit/lod/cut/kept_subtrees.h"
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
    Planner(const Model& model, const std::vector<std::vector<Proxy>>& proxies, const PlanPrices& prices,
            double budget)
        : model_(model),
          proxies_(proxies),
          prices_(prices),
          budget_(budget),
          state_(model.nodes.size(), -1),
          drawn_(prices.paid) {
        for (std::size_t n = 0; n < model.nodes.size(); ++n)
            if (!proxies[n].empty()) state_[n] = 0;  // the cheapest, until changed
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
        return s >= 0 ? proxies_[std::size_t(n)][std::size_t(s)].bytes
                      : prices_.subtree_bytes[std::size_t(n)];
    }
    const std::vector<int>& drawn_textures(int n) const {
        const int s = state_[std::size_t(n)];
        return s >= 0 ? prices_.proxy_textures[std::size_t(n)][std::size_t(s)]
                      : prices_.subtree_textures[std::size_t(n)];
    }
    double drawn_error(int n) const {
        const int s = state_[std::size_t(n)];
        return s >= 0 ? proxies_[std::size_t(n)][std::size_t(s)].error : 0;
    }

    // The textures of what node n draws after changing to `proxy` (-1: opened).
    std::vector<const std::vector<int>*> added_textures(int n, int proxy) const {
        if (proxy >= 0) return {&prices_.proxy_textures[std::size_t(n)][std::size_t(proxy)]};
        std::vector<const std::vector<int>*> added{&prices_.own_textures[std::size_t(n)]};
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
            move.cost += prices_.own_bytes[std::size_t(n)];
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
    const PlanPrices& prices_;
    double budget_;
    std::vector<int> state_;
    DrawnTextures drawn_;
    std::set<Key, KeyOrder> frontier_;
};

}  // namespace

PlanPrices plan_prices(const Model& model, const std::vector<std::vector<Proxy>>& proxies) {
    PlanPrices prices{paid_textures(model), {}, {}, {}, {}, {}};
    prices.own_textures = node_textures(model, prices.paid);
    prices.subtree_textures = subtree_textures(model, prices.paid);
    const std::vector<std::uint64_t> subtree = subtree_mesh_bytes(model);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        prices.subtree_bytes.push_back(double(subtree[n]));
        prices.own_bytes.push_back(double(mesh_bytes(model.nodes[n].primitives, model)));
        prices.proxy_textures.emplace_back();
        for (const Proxy& proxy : proxies[n])
            prices.proxy_textures.back().push_back(proxy_textures(prices.paid, proxy));
    }
    return prices;
}

void order_within(const Model& model, const std::vector<std::vector<Proxy>>& proxies,
                  const PlanPrices& prices, double budget, std::vector<HybridStep>& steps,
                  std::vector<double>& bytes, std::vector<double>& error, const std::vector<int>* start) {
    Planner(model, proxies, prices, budget).run(start, steps, bytes, error);
}

namespace {

// lambda's 18 decades to a hundred-millionth of one
constexpr int pruning_bisections = 32;

// The state minimizing error + lambda x bytes, each part priced with the
// textures it samples alone, and its bytes so priced.
std::pair<std::vector<int>, double> pruned_state(const Model& model,
                                                 const std::vector<std::vector<Proxy>>& proxies,
                                                 const PlanPrices& prices, double lambda) {
    const PaidTextures& paid = prices.paid;
    const std::size_t count = model.nodes.size();
    std::vector<double> value(count), bytes(count);
    std::vector<int> choice(count, -1);
    for (std::size_t n = count; n-- > 0;) {  // children after their parents (model.h)
        if (proxies[n].empty()) {            // drawn whole where reached
            bytes[n] = prices.subtree_bytes[n] + bytes_of(paid, prices.subtree_textures[n]);
            value[n] = lambda * bytes[n];
            continue;
        }
        bytes[n] = prices.own_bytes[n] + bytes_of(paid, prices.own_textures[n]);
        value[n] = lambda * bytes[n];
        for (int child : model.nodes[n].children) {
            bytes[n] += bytes[std::size_t(child)];
            value[n] += value[std::size_t(child)];
        }
        for (std::size_t p = 0; p < proxies[n].size(); ++p) {
            const double alone = proxies[n][p].bytes + bytes_of(paid, prices.proxy_textures[n][p]);
            if (const double v = proxies[n][p].error + lambda * alone; v < value[n]) {
                value[n] = v;
                bytes[n] = alone;
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
                                     const PlanPrices& prices, double budget) {
    // The least lambda (pixels of error per byte) whose cut fits, by bisection
    // of its logarithm, as a cut's bytes fall while lambda grows: at 1e6 no
    // change pays, at 1e-12 each that gains a thousandth of a pixel for a
    // gigabyte does; the greedy order fills what the cut leaves of the budget.
    double low = 1e-12, high = 1e6;
    for (int k = 0; k < pruning_bisections; ++k) {
        const double lambda = std::sqrt(low * high);
        (pruned_state(model, proxies, prices, lambda).second <= budget ? high : low) = lambda;
    }
    return pruned_state(model, proxies, prices, high).first;
}

}  // namespace boxlod
