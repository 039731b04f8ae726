#include "base/graph_check.h"

#include "base/input_error.h"

#include <algorithm>

namespace boxlod {

void check_acyclic_and_shallow(const std::vector<std::vector<std::uint32_t>>& edges,
                               const std::function<std::string(std::uint32_t)>& place_of,
                               const std::string& what, const std::string& file, int max_depth) {
    enum State : std::uint8_t { unseen, open, done };
    std::vector<State> state(edges.size(), unseen);
    std::vector<int> height(edges.size(), 0);
    struct Frame {
        std::uint32_t node;
        std::size_t next;
    };
    for (std::uint32_t root = 0; root < edges.size(); ++root) {
        if (state[root] != unseen) continue;
        std::vector<Frame> stack{{root, 0}};
        state[root] = open;
        while (!stack.empty()) {
            Frame& frame = stack.back();
            if (frame.next < edges[frame.node].size()) {
                std::uint32_t child = edges[frame.node][frame.next++];
                if (state[child] == open) throw_input_error(file, place_of(child), what + " form a cycle");
                if (state[child] == unseen) {
                    if (stack.size() >= std::size_t(max_depth))
                        throw_input_error(file, place_of(child), what + " " + nesting_message());
                    state[child] = open;
                    stack.push_back({child, 0});
                }
                continue;
            }
            int h = 0;
            for (std::uint32_t child : edges[frame.node]) h = std::max(h, height[child] + 1);
            // h edges below it: h + 1 nodes, as the stack counts them.
            if (h >= max_depth) throw_input_error(file, place_of(frame.node), what + " " + nesting_message());
            height[frame.node] = h;
            state[frame.node] = done;
            stack.pop_back();
        }
    }
}

}  // namespace boxlod
