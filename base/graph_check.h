// A graph read from a file (references between its records) that a reader
// will walk by recursion: it must hold no cycle, and no path deeper than the
// reader's limit.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace boxlod {

// Depth-first over `edges` (each node's successors) with an explicit stack:
// throws InputError(file, place_of(node), what + " form a cycle" or what +
// " nested more than max_depth levels deep") at the node where a cycle or a
// path longer than max_depth is found.
void check_acyclic_and_shallow(const std::vector<std::vector<std::uint32_t>>& edges,
                               const std::function<std::string(std::uint32_t)>& place_of,
                               const std::string& what, const std::string& file, int max_depth);

}  // namespace boxlod
