#include "toolkit/lod/lod_builder.h"
#include "toolkit/lod/cut/level_values.h"

#include "base/input_error.h"
#include "base/parallel.h"
#include "base/timing.h"
#include "toolkit/lod/cut/error_greedy.h"
#include "toolkit/lod/cut/kept_subtrees.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/level_faces.h"
#include "toolkit/model/cost.h"
#include "toolkit/model/framing.h"
#include "toolkit/model/model_subtree.h"
#include "toolkit/model/statistics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

namespace boxlod {
namespace {

// Level c's budget in bytes (level_budgets.h), c >= 1 when the parameters give budgets.
double level_budget(const LodSession& session, int level) {
    const double original_bytes = double(session.derived.original_cost.bytes());
    return budget_bytes(session.input.parameters.budgets[std::size_t(level - 1)], original_bytes);
}

// The level values of the session's level mode; hybrid and error-greedy with
// budgets also make the plan whose prefixes the levels are, and each level's prefix.
void derive_levels(LodSession& session, int threads, HybridMeasurements* measurements) {
    const Model& model = *session.input.model;
    const LodParameters& p = session.input.parameters;
    LodDerived& d = session.derived;
    const int levels = asked_levels(p);
    std::vector<double> budgets;  // levels 1..N, bytes
    for (std::size_t c = 1; c <= p.budgets.size(); ++c) budgets.push_back(level_budget(session, int(c)));
    const bool textured = p.render_mode != RenderMode::untextured;
    if (p.level_mode == LevelMode::hybrid) {
        d.hybrid = std::make_shared<const HybridPlan>(plan_hybrid(model, d.textures, d.boxes,
                                                                  {.sizing = d.sizing,
                                                                   .mode = p.render_mode,
                                                                   .threads = threads,
                                                                   .measurements = measurements,
                                                                   .baked_proxies = p.baked_proxies}));
        if (budgets.empty())
            budgets = geometric_budgets(d.hybrid->bytes.front(), d.hybrid->bytes.back(), levels);
        d.levels = hybrid_levels(model, *d.hybrid, budgets, session.cache.hybrid_levels);
    } else if (p.level_mode == LevelMode::error_greedy && !budgets.empty()) {
        d.opening = std::make_shared<const GreedyOpening>(greedy_opening(model, d.boxes, d.sizing, textured));
        session.cache.opening_steps = greedy_prefixes(*d.opening, budgets);
        d.levels = {opened_levels(model, *d.opening, session.cache.opening_steps), levels};
    } else {
        d.levels =
            compute_level_values(model, p.level_mode, levels, p.interpolation, d.boxes, d.sizing, textured);
    }
}

}  // namespace

std::unique_ptr<LodSession> start_lod(const Model& model, const LodParameters& parameters, int threads,
                                      const std::vector<std::optional<OrientedBox>>* boxes,
                                      HybridMeasurements* measurements) {
    if (model.is_lod)
        throw_input_error(model.source, "",
                          "is an LoD exported by boxlod: it can be viewed, but not simplified again");
    if (!draws_anything(
            model))  // every level would be empty (teapots.DAE: a transparency of "0,200000" read as 0)
        throw_input_error(model.source, "",
                          "every surface is fully transparent (opacity 0): nothing to draw or bake");
    validate_parameters(parameters, model.source);
    if (!parameters.budgets.empty() &&
        !orders_by_bytes(parameters.level_mode))  // a sweep drops them for the other modes
        throw_input_error(model.source, "",
                          std::string("--budgets: level mode ") + level_mode_name(parameters.level_mode) +
                              " does not order its cuts by bytes; budgets are for error-greedy and hybrid");
    auto session = std::make_unique<LodSession>();
    session->input.model = &model;
    session->input.parameters = parameters;
    LodParameters& p = session->input.parameters;
    LodDerived& d = session->derived;
    if (p.model.empty()) p.model = model.source;
    if (p.distance == 0) p.distance = framing_distance(model_framing(model), p.fovy);
    if (!parameter_range::distance.contains(p.distance))  // a model a billion metres wide seen through 0.1°
        throw_input_error(model.source, "",
                          "the distance that frames it at fovy " + format_number(p.fovy) + ", " +
                              format_number(p.distance) + ", lies outside distance's " +
                              range_text(parameter_range::distance) + " (set --distance or --fovy)");
    d.sizing = {p.fovy, p.distance, p.resolution, p.max_texture_size, 2};
    d.boxes =
        timed(session->times.boxes, [&] { return boxes ? *boxes : node_boxes(model, p.box_kind, threads); });
    // hybrid measures its proxies against the textured original, whatever the levels' render mode.
    if (p.render_mode != RenderMode::untextured || p.level_mode == LevelMode::hybrid)
        d.textures = decode_textures(model);
    {
        const ScopedTimer timer(session->times.levels);
        d.depth_errors = box_depth_errors(model, d.boxes);
        d.original_cost = model_cost(model);
        derive_levels(*session, threads, measurements);
    }
    // hybrid's plan keeps what pays (hybrid.h); with budgets the budget decides (level_budgets.h).
    if ((p.keep_small_subtrees || p.keep_cheaper_subtrees) && !d.hybrid && p.budgets.empty())
        d.kept = kept_subtrees(model, d.boxes, {p.keep_small_subtrees, p.keep_cheaper_subtrees}, d.sizing,
                               p.render_mode != RenderMode::untextured);
    return session;
}

namespace {

// Copies of `primitives` into `node`, their materials the output's (copied on first use).
void add_primitives(const std::vector<Primitive>& primitives, MaterialCopier& writer, Node& node) {
    for (const Primitive& primitive : primitives) {
        Primitive copy = primitive;
        copy.material = writer.material(primitive.material);
        node.primitives.push_back(std::move(copy));
    }
}

// Mesh: the cut's nodes in tree order; a kept node brings its geometry (and its
// materials and textures), a simplified one its simplified sub-tree, a box
// node becomes a leaf with one quad per packed face, a baked one a leaf with
// its proxy's triangles on the pages.
void add_cut_nodes(Model& out, const LodSession& session, const Cut& cut, const Packing& packing,
                   const Atlas& atlas, bool textured) {
    const Model& model = *session.input.model;
    MaterialCopier writer{model, out};
    std::vector<bool> is_box(model.nodes.size(), false), is_baked(model.nodes.size(), false);
    for (int n : cut.box_nodes) is_box[n] = true;
    for (const BakedNode& baked : cut.baked_nodes) is_baked[std::size_t(baked.node)] = true;
    std::map<int, const Proxy*> simplified;
    for (auto [n, proxy] : cut.simplified_nodes)
        simplified[n] = &session.derived.hybrid->proxies[std::size_t(n)][std::size_t(proxy)];
    std::map<int, int> new_index, baked_materials;
    if (textured) place_packed_faces(session, cut, packing, atlas, out);
    for (int n : cut.used_nodes) {
        const Node& node = model.nodes[n];
        int parent = node.parent >= 0 ? new_index.at(node.parent) : -1;
        int index = add_node(out, parent, node.name);
        new_index[n] = index;
        out.nodes[index].rule = node.rule;
        out.nodes[index].scope = node.scope;
        out.nodes[index].source_id = node.source_id;
        std::map<int, Primitive> by_page;
        if (auto proxy = simplified.find(n); proxy != simplified.end())  // the source's materials
            add_primitives(proxy->second->primitives, writer, out.nodes[index]);
        else if (is_baked[n])
            by_page = baked_primitives(n, packing, atlas, baked_materials, out);
        else if (is_box[n])
            by_page = box_primitives(session, cut, n, packing, atlas, textured);
        else  // kept: its own geometry (a replaced node without box has none)
            add_primitives(node.primitives, writer, out.nodes[index]);
        for (auto& [page, primitive] : by_page) out.nodes[index].primitives.push_back(std::move(primitive));
    }
    if (packing.swatch_placement >= 0)
        place_swatches(packing.swatches, atlas.placements[std::size_t(packing.swatch_placement)],
                       session.derived.sizing.gutter, out);
}

// Statistics (docs/design.md: Statistics); occupancy = the faces' own texels / page texels.
KeyValues lod_statistics(const LodSession& session, const Lod& lod, const Packing& packing) {
    const Model& model = *session.input.model;
    int largest_page_side = 0;
    std::string page_list;
    for (const Eigen::Vector2i& page : lod.atlas.pages) {
        largest_page_side = std::max({largest_page_side, page.x(), page.y()});
        page_list +=
            (page_list.empty() ? "" : ", ") + std::to_string(page.x()) + "x" + std::to_string(page.y());
    }
    const double occupancy =
        lod.atlas.pages.empty() ? 0 : double(lod.face_texels) / double(page_texels(lod.atlas));
    MeshCounts lod_counts = mesh_counts(lod.model), original = mesh_counts(model);
    Eigen::Vector3f size = model_bounds(model).size();
    KeyValues statistics = {
        number_entry("nodes", double(model.nodes.size())),
        number_entry("used_nodes", double(lod.cut.used_nodes.size())),
        number_entry("nodes_with_geometry", double(lod.cut.geometry_nodes.size())),
        number_entry("nodes_with_box", double(lod.cut.box_nodes.size())),
        number_entry("nodes_simplified", double(lod.cut.simplified_nodes.size())),
        number_entry("nodes_baked", double(lod.cut.baked_nodes.size())),
        number_entry("depth", tree_depth(model)),
        number_entry("batches_lod", double(lod_counts.batches)),
        number_entry("faces_lod", double(lod_counts.faces)),
        number_entry("triangles_lod", double(lod_counts.triangles)),
        number_entry("vertices_lod", double(lod_counts.vertices)),
        number_entry("batches_original", double(original.batches)),
        number_entry("faces_original", double(original.faces)),
        number_entry("triangles_original", double(original.triangles)),
        number_entry("vertices_original", double(original.vertices)),
        float_entry("min_distance", packing.longest_face > 0
                                        ? min_distance(packing.longest_face, session.derived.sizing)
                                        : 0),
        float_entry("mesh_width", size.x()),
        float_entry("mesh_height", size.y()),
        float_entry("mesh_depth", size.z()),
        number_entry("lod_textures", double(lod.atlas.pages.size())),
        number_entry("texture_size", largest_page_side),
        text_entry("texture_pages", page_list),
        number_entry("page_texels", double(page_texels(lod.atlas))),
        number_entry("face_texels", double(lod.face_texels)),
        number_entry("gutter_texels", double(packing.gutter_texels)),
        number_entry("occupancy", occupancy),
        number_entry("flat_faces", packing.flat_faces),
        number_entry("swatches", double(packing.swatches.colors.size())),
        number_entry("depth_error", lod.depth_error),
        number_entry("measured_error", lod.measured_error),
    };
    for (const KeyValues& cost : {cost_entries(combined_cost({&lod.cost}), "_lod"),
                                  cost_entries(session.derived.original_cost, "_original")})
        statistics.insert(statistics.end(), cost.begin(), cost.end());
    if (!session.input.parameters.budgets.empty() && lod.current_level >= 1)  // what it spent is bytes_lod
        statistics.push_back(
            number_entry("budget_bytes", std::floor(level_budget(session, lod.current_level))));
    statistics.push_back(number_entry("obtained_levels", session.derived.levels.obtained_levels));
    statistics.push_back(
        number_entry("current_level", lod.current_level));  // last: it closes a level's block
    return statistics;
}

}  // namespace

namespace {

// The build as named steps from the cut: bake, pack, page, mesh, statistics.
Lod build_cut(LodSession& session, int current_level, Cut cut, int threads) {
    const Model& model = *session.input.model;
    const LodParameters& p = session.input.parameters;
    const bool textured = p.render_mode != RenderMode::untextured;
    Lod lod;
    lod.current_level = current_level;
    lod.cut = std::move(cut);
    for (int node : lod.cut.box_nodes) lod.depth_error += session.derived.depth_errors[std::size_t(node)];
    if (session.derived.hybrid) lod.measured_error = hybrid_cut_error(*session.derived.hybrid, lod.cut);
    if (textured) {
        const ScopedTimer timer(session.times.bake);
        bake_new_faces(session, lod.cut, threads);
    }
    Packing packing = timed(session.times.pack, [&] {
        Packing plain = pack_faces(session, lod.cut, textured, 0, threads);
        if (p.flat_faces > 0 && textured) {  // flat faces only where they save page texels: else they would
                                             // lose detail for nothing
            Packing flat = pack_faces(session, lod.cut, textured, p.flat_faces, threads);
            if (page_texels(flat.atlas) < page_texels(plain.atlas)) return flat;
        }
        return plain;
    });
    lod.atlas = std::move(
        packing.atlas);  // packing.faces[i] lies at placements[faces[i].placement] (flat: the swatches')
    lod.face_texels = packing.face_texels;

    {
        const ScopedTimer timer(session.times.mesh);
        Model& out = lod.model;
        keep_provenance(model, out);
        out.is_lod = true;
        LodParameters saved = p;
        saved.current_level = current_level;
        // A shipped asset names its model by file name: no builder's folder leaks
        // into it, and a build in any folder gives the same bytes.
        saved.model = std::filesystem::path(p.model).filename().string();
        for (const KeyValue& entry : parameter_entries(saved))
            out.lod_params.emplace_back(entry.key, entry.value);
        check_pages_memory(session, lod.atlas);
        add_pages(out, lod.atlas, packing.height_depth, textured);
        lod.pages_held = hold_pages(lod.atlas);
        add_cut_nodes(out, session, lod.cut, packing, lod.atlas, textured);
    }

    lod.cost = cost_parts(lod.model);
    lod.statistics = lod_statistics(session, lod, packing);
    for (BakedNode& baked : lod.cut.baked_nodes)
        baked.geometry = nullptr;  // the plan's or the caller's: not kept past the build
    return lod;
}

// The cut of level c as the session holds it: a hybrid state, error-greedy's
// openings within a budget, or the level values.
Cut level_cut(const LodSession& session, int c) {
    const Model& model = *session.input.model;
    const LodDerived& d = session.derived;
    if (d.hybrid) return hybrid_cut(model, *d.hybrid, session.cache.hybrid_levels[std::size_t(c)].state);
    if (d.opening && c >= 1) {
        const std::size_t steps = session.cache.opening_steps[std::size_t(c)];
        return take_cut(model, opened_levels(model, *d.opening, {steps, steps}), 1, d.boxes, d.kept);
    }
    return take_cut(model, d.levels.level, c, d.boxes, d.kept);
}

double spent_bytes(const Lod& lod) { return double(combined_cost({&lod.cost}).bytes()); }

std::string budget_problem(int level, double budget, double coarsest) {
    return "--budgets: level " + std::to_string(level) + "'s budget of " + format_number(std::floor(budget)) +
           " bytes is below the coarsest cut's " + format_number(coarsest) + " bytes";
}

// Level c as the best within `estimate` bytes; below 0: the coarsest cut (the root's cheapest proxy, or its
// box).
void set_level_within(LodSession& session, int c, double estimate) {
    const LodDerived& d = session.derived;
    if (d.hybrid)
        session.cache.hybrid_levels[std::size_t(c)] =
            hybrid_level_within(*session.input.model, *d.hybrid, estimate);
    else
        session.cache.opening_steps[std::size_t(c)] =
            estimate < 0 ? 0 : longest_prefix_within(d.opening->bytes, estimate);
}

// Level c's place in its mode's order (a hybrid state, error-greedy's
// openings), to be set back; and the error its mode estimates for it.
struct LevelChoice {
    HybridLevel hybrid;
    std::size_t opening_steps = 0;
};

LevelChoice level_choice(const LodSession& session, std::size_t level) {
    if (session.derived.hybrid) return {session.cache.hybrid_levels[level], 0};
    return {{}, session.cache.opening_steps[level]};
}

void set_level_choice(LodSession& session, std::size_t level, const LevelChoice& choice) {
    if (session.derived.hybrid)
        session.cache.hybrid_levels[level] = choice.hybrid;
    else
        session.cache.opening_steps[level] = choice.opening_steps;
}

double estimated_bytes(const LodSession& session, std::size_t level) {
    const LodCache& cache = session.cache;
    return session.derived.hybrid ? cache.hybrid_levels[level].bytes
                                  : session.derived.opening->bytes[cache.opening_steps[level]];
}

double estimated_error(const LodSession& session, std::size_t level) {
    const LodCache& cache = session.cache;
    return session.derived.hybrid ? cache.hybrid_levels[level].error
                                  : session.derived.opening->error[cache.opening_steps[level]];
}

// The estimates miss a level's real bytes (pages round up to powers of two,
// each face brings a gutter; error-greedy's leave out the original's
// textures): while the level spends more than its budget, ask for a level
// whose estimate lies below every one tried so far, in proportion to the
// overshoot, and failing that build the coarsest cut once. The estimates fall
// every time, so this ends. When nothing fits, a sweep (budgets_strict off)
// takes the cheapest level built.
Lod shrink_to_budget(LodSession& session, Lod lod, int threads) {
    const int c = lod.current_level;
    const double budget = level_budget(session, c);
    const std::size_t level = std::size_t(c);
    double ceiling = estimated_bytes(session, level), spent = spent_bytes(lod);
    std::optional<Lod> cheapest;  // kept only where nothing fitting is no error
    if (!session.input.budgets_strict) cheapest = lod;
    bool coarsest = false;
    while (spent > budget) {
        set_level_within(session, c, std::min(ceiling * budget / spent, std::nextafter(ceiling, 0.0)));
        if (estimated_bytes(session, level) >= ceiling) {  // no cheaper estimate
            if (coarsest) {
                if (!cheapest)
                    throw_input_error(session.input.model->source, "", budget_problem(c, budget, spent));
                return std::move(*cheapest);  // over its budget, as its statistics say
            }
            set_level_within(session, c, -1);
            coarsest = true;
        }
        ceiling = std::min(ceiling, estimated_bytes(session, level));
        lod = build_cut(session, c, level_cut(session, c), threads);
        spent = spent_bytes(lod);
        if (cheapest && spent < spent_bytes(*cheapest)) cheapest = lod;
    }
    return lod;
}

// The estimates miss the other way too: a coarse box whose faces are drawn
// flat costs a swatch, not the pages its estimate counts (on `office`, a
// hybrid level within 5 % of the bytes spent 44 % of its budget). While a
// level fitting its budget spends less than 95 % of it, ask for one within a
// larger estimate, in proportion to the shortfall, or halfway to the least
// estimate whose level spent too much; keep a level that fits and has a lower
// estimated error. Where that ask is no more than the last (the level's
// estimate was no dearer than what it spent, or a larger estimate gave the
// same level, as hybrid's pruned cuts jump: hybrid_order.h), ask for
// budget / spent times the last; an ask that gives the level that spent too
// much is too much, unbuilt. At most 4 more builds and 8 asks.
Lod grow_to_budget(LodSession& session, Lod lod, int threads) {
    constexpr int most_builds = 4, most_asks = 8;
    constexpr double full = 0.95;
    const int c = lod.current_level;
    const double budget = level_budget(session, c);
    const auto level = std::size_t(c);
    LevelChoice kept = level_choice(session, level);
    double kept_error = estimated_error(session, level);
    double estimate = estimated_bytes(session, level),
           spent = spent_bytes(lod);  // of the last level built that fit
    double asked = budget, too_much = std::numeric_limits<double>::infinity();  // estimates asked for
    double too_much_estimate = -1;  // of the level that spent too much
    for (int build = 0, asks = 0; build < most_builds && asks < most_asks && spent < full * budget; ++asks) {
        double ask = std::isinf(too_much) ? estimate * budget / spent : (asked + too_much) / 2;
        if (std::isinf(too_much) && !(ask > asked)) ask = asked * budget / spent;
        if (!(ask > asked)) break;
        set_level_within(session, c, ask);
        const double now = estimated_bytes(session, level);
        if (now == estimate) {  // no other level up to there
            asked = ask;
            continue;
        }
        if (now == too_much_estimate) {  // the level that spent too much
            too_much = ask;
            continue;
        }
        ++build;
        Lod grown = build_cut(session, c, level_cut(session, c), threads);
        if (spent_bytes(grown) > budget) {
            too_much = ask;
            too_much_estimate = now;
            continue;
        }
        asked = ask;
        estimate = estimated_bytes(session, level);
        spent = spent_bytes(grown);
        if (estimated_error(session, level) < kept_error) {
            lod = std::move(grown);
            kept = level_choice(session, level);
            kept_error = estimated_error(session, level);
        }
    }
    set_level_choice(session, level, kept);
    return lod;
}

Lod fit_to_budget(LodSession& session, Lod lod, int threads) {
    const bool fitted = spent_bytes(lod) <= level_budget(session, lod.current_level);
    lod = shrink_to_budget(session, std::move(lod), threads);
    return fitted ? grow_to_budget(session, std::move(lod), threads) : lod;
}

}  // namespace

Lod build_lod(LodSession& session, int current_level, int threads) {
    const int obtained = session.derived.levels.obtained_levels;
    if (current_level < 0 || current_level > obtained)
        throw InputError("current level " + std::to_string(current_level) + " is outside 0.." +
                         std::to_string(obtained) + " (the obtained number of levels)");
    Lod lod = build_cut(session, current_level, level_cut(session, current_level), threads);
    return session.input.parameters.budgets.empty() || current_level == 0
               ? lod
               : fit_to_budget(session, std::move(lod), threads);
}

Lod build_baked_model(LodSession& session, const std::vector<Primitive>& geometry, int texel_scale, int level,
                      int threads) {
    if (!session.derived.boxes[0])
        throw_input_error(session.input.model->source, "", "has no geometry to bake a proxy from");
    if (session.input.parameters.render_mode == RenderMode::untextured)
        throw_input_error(session.input.model->source, "",
                          "a baked proxy draws baked pages: its levels cannot be untextured");
    Cut cut;
    cut.used_nodes = {0};
    cut.baked_nodes = {{0, -1, &geometry}};
    if (texel_scale > 1) cut.box_texel_scales[0] = texel_scale;
    return build_cut(session, level, std::move(cut), threads);
}

void check_budget_reachable(LodSession& session, int level, int threads) {
    const std::vector<ByteBudget>& budgets = session.input.parameters.budgets;
    if (budgets.empty() || level < 1 || level > int(budgets.size())) return;
    // The coarsest cut built for real, its level then set back as it was.
    const LevelChoice chosen = level_choice(session, std::size_t(level));
    set_level_within(session, level, -1);
    const double coarsest = spent_bytes(build_cut(session, level, level_cut(session, level), threads));
    set_level_choice(session, std::size_t(level), chosen);
    if (coarsest > level_budget(session, level))
        throw_input_error(session.input.model->source, "",
                          budget_problem(level, level_budget(session, level), coarsest));
}

}  // namespace boxlod
