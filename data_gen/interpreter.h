// Derives a grammar into the scene model: one node per rule application (the
// derivation tree), each with the scope its symbol was given and the rule's
// name, and geometry at the nodes whose rules insert it (in world space, Y up,
// metres).
#pragma once
#include "data_gen/grammar.h"
#include "data_gen/materials.h"
#include "data_gen/scope_box.h"
#include "toolkit/model/model.h"

#include <cstdint>
#include <optional>
#include <string>

namespace boxlod {

// Guards against grammars that never stop: a rule nested deeper than
// `max_depth`, or one derivation making more than `max_nodes` nodes or more
// than `max_shapes` split pieces and components (which make no node where they
// are NIL: splits nested inline multiply), is an InputError.
// No scope may reach further from the origin, or be larger, than this (metres):
// a value such as extrude(1e39) is refused where it is made, not as NaN later.
constexpr float max_world_extent = 1e6f;

struct DerivationLimits {
    int max_depth = 100;
    std::size_t max_nodes = 2'000'000;
    std::size_t max_shapes = 8'000'000;  // 0.2 s and at most 256 MB of split layouts (32 bytes a piece)
};

// Applies `start` ("" = the first rule) to the scope `lot` and appends the
// derivation tree under `parent` (-1: as the model's root). Random choices
// come from streams keyed by `seed` and each node's place in the tree.
// Returns the new subtree's root node.
int derive(const Grammar& grammar, const std::string& start, const ScopeBox& lot, std::uint64_t seed,
           Model& model, int parent, MaterialCache& materials, const DerivationLimits& limits = {});

// The lot a grammar asks for with `attr lot_width = ...` and
// `attr lot_depth = ...`; 20 x 20 m when it does not say.
Eigen::Vector2f default_lot(const Grammar& grammar, std::uint64_t seed);

// A flat lot of `width` x `depth` on the ground (y = 0), centred at the origin.
ScopeBox ground_lot(float width, float depth, const Eigen::Vector3f& center = Eigen::Vector3f::Zero());

struct BuildingOptions {
    std::string start;                   // "" = the grammar's first rule
    std::optional<Eigen::Vector2f> lot;  // width x depth; default: default_lot()
    std::uint64_t seed = 0;
    DerivationLimits limits;
};

// One building as a whole model.
Model generate_building(const Grammar& grammar, const BuildingOptions& options);

}  // namespace boxlod
