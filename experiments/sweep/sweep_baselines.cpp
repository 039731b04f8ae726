#include "experiments/sweep/sweep_baselines.h"

#include "base/csv.h"
#include "base/key_values.h"
#include "experiments/sweep/file_lods.h"
#include "experiments/sweep/impostor.h"
#include "experiments/sweep/proxy_baked.h"
#include "experiments/sweep/single_box.h"
#include "experiments/sweep/sweep_shots.h"
#include "experiments/sweep/within_budget.h"
#include "toolkit/cgal/cgal_simplification.h"
#include "toolkit/formats/model_io.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/hybrid/simplification.h"
#include "toolkit/model/statistics.h"

#include <algorithm>
#include <optional>

namespace boxlod {
namespace {

// The `triangles` column of a results.csv row (after the key columns, obtained_levels and faces).
std::size_t triangles_of_row(const std::string& row) {
    return std::stoull(csv_fields(row).at(sweep_key_columns().size() + 2));
}

// The impostor: one atlas per model, captured for texel = pixel at the nearest of the
// distances; each view and distance draws the quad of the direction nearest its camera.
// file-lods: each of a CityJSON model's LoDs coarser than the one read, a group of its own.
void run_file_lods(ModelRun& run, SweepOutput& out, SweepReport& report, int obtained_levels) {
    auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
    const std::vector<std::string> lods = coarser_file_lods(run.config.lod.city_lod, run.entry.path);
    for (std::size_t k = 0; k < lods.size(); ++k)
        run_group(run, out, report, csv_row({run.entry.name, "file-lods", "-", "-", std::to_string(k + 1)}),
                  one_slot, [&](int, int) {
                      SweepCandidate c =
                          candidate(load_model(run.entry.path, {.chain_level = 0, .city_lod = lods[k]}), {},
                                    0, obtained_levels);
                      c.variant = "LoD " + lods[k];
                      return c;
                  });
}

void run_impostor(ModelRun& run, SweepOutput& out, SweepReport& report, const std::string& group, int level) {
    const SweepConfig& config = run.config;
    std::optional<ImpostorAtlas> atlas;
    TextureCache decoded;  // every view's quad draws the same atlas: decoded once
    auto view_slot = [&](RenderMode, std::size_t v, std::size_t d) {
        return int(v * config.distances.size() + d);
    };
    run_group(run, out, report, group, view_slot, [&](int s, int) {
        const std::size_t v = std::size_t(s) / config.distances.size(),
                          d = std::size_t(s) % config.distances.size();
        if (!atlas) {
            TextureSizing sizing;
            sizing.fovy_degrees = config.lod.fovy;
            sizing.resolution = config.lod.resolution;
            sizing.distance = *std::min_element(config.distances.begin(), config.distances.end()) *
                              framing_distance(run.framing, config.lod.fovy);
            int cell = impostor_cell(model_bounds(run.model), pixel_world_size(sizing));
            atlas = make_impostor(run.model, config.impostor_directions, cell, run.threads);
        }
        Eigen::Vector3f eye = view_settings(run.framing, config.views[v], config.distances[d],
                                            RenderMode::normal, config.lod, run.threads)
                                  .camera.position;
        SweepCandidate c = candidate(impostor_model(*atlas, eye, run.model.source), {}, 0, level);
        c.variant = "direction " + std::to_string(nearest_direction(*atlas, eye));
        c.drawable = make_drawable_model(c.model, &decoded, run.threads);
        return c;
    });
}

// Levels by byte budget: a baseline's level c >= 1 as finely as budget c
// allows (equal bytes, not equal triangles), in bytes; -1 where levels are not by budget.
double level_budget(const ModelRun& run, const SweepVariant& first, int level) {
    const LodParameters& lod = run.config.lod;
    if (!orders_by_bytes(first.mode) || lod.budgets.empty() || level == 0) return -1;
    return budget_bytes(lod.budgets[std::size_t(level - 1)], double(model_cost(run.model).bytes()));
}

// proxy-baked: per level but the original (a baked copy of it is no level)
// the best of its variants that fit the level's budget (or at its
// triangles), baked as the first variant's level is sized (sizing
// each-distance: for the nearest distance, as the impostor; one chain per
// sizing level, which bakes the root's box once).
void run_proxy_baked(ModelRun& run, SweepOutput& out, SweepReport& report, const SweepVariant& first,
                     const std::function<std::size_t(int)>& triangles_of_level) {
    const SweepConfig& config = run.config;
    const std::vector<ProxyBakedVariant> variants = proxy_baked_variants(run.threads);
    const double nearest = *std::min_element(config.distances.begin(), config.distances.end()) *
                           framing_distance(run.framing, config.lod.fovy);
    // Where the first variant's chain sizes each level: with its budgets, no farther than their share
    // (chain.h).
    const std::vector<float> sized =
        level_distances({}, float(nearest), first.obtained_levels,
                        orders_by_bytes(first.mode) ? config.lod.budgets : std::vector<ByteBudget>{});
    std::map<int, std::unique_ptr<Chain>> chains;  // per sizing level
    for (int level : first.levels) {
        if (level == 0) continue;
        const int sizing_level = config.sizing == SizingRule::per_level ? level : 1;
        const double budget = level_budget(run, first, level);
        auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
        const std::string group = csv_row({run.entry.name, "proxy-baked", "-", "-", std::to_string(level)});
        run_group(
            run, out, report, group, one_slot,
            [&](int, int a) {
                std::unique_ptr<Chain>& chain = chains[sizing_level];
                if (!chain)
                    chain = std::make_unique<Chain>(
                        run.model, proxy_baked_parameters(config.lod, sized[std::size_t(sizing_level - 1)]),
                        run.threads);
                const ProxyBakedVariant& v = variants[std::size_t(a)];
                Lod lod = proxy_baked_level(*chain, v, triangles_of_level(level), budget, level);
                SweepCandidate c = candidate(std::move(lod.model), std::move(lod.atlas), 0,
                                             first.obtained_levels, &lod.cost);
                c.face_texels = lod.face_texels;
                c.variant = v.name;
                return c;
            },
            int(variants.size()), budget);
    }
}

// simplification: the first of simplify_variants (boxlod simplify's) at each level's triangles or
// budget; simplification-best: the best of them all; cgal: Garland-Heckbert's edge collapse.
void run_simplification(ModelRun& run, SweepOutput& out, SweepReport& report, const SweepVariant& first,
                        Baseline baseline, const std::function<std::size_t(int)>& triangles_of_level) {
    const std::vector<SimplifyVariant> variants = simplify_variants(run.threads);
    const std::string name = enum_name(baselines(), baseline);
    auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
    const int alternatives = baseline == Baseline::simplification_best ? int(variants.size()) : 1;
    for (int level : first.levels) {
        const std::size_t target = triangles_of_level(level);
        const double budget = level_budget(run, first, level);
        auto simplified =
            [&](const std::function<Model(std::size_t)>& simplify) {  // bytes: cost.h, every texture
                if (budget < 0) return simplify(target);
                return finest_within<Model>(
                    mesh_counts(run.model).triangles, budget, simplify,
                    [](const Model& model) { return double(model_cost(model).bytes()); });
            };
        run_group(
            run, out, report, csv_row({run.entry.name, name, "-", "-", std::to_string(level)}), one_slot,
            [&](int, int a) {
                if (baseline == Baseline::cgal) {
                    SweepCandidate c =
                        candidate(simplified([&](std::size_t t) { return cgal_simplify(run.model, t); }), {},
                                  0, first.obtained_levels);
                    c.variant = "garland-heckbert";
                    return c;
                }
                const SimplifyVariant& v = variants[std::size_t(a)];
                SweepCandidate c = candidate(
                    simplified([&](std::size_t t) { return simplify_model(run.model, t, v.options); }), {}, 0,
                    first.obtained_levels);
                c.variant = v.name;
                return c;
            },
            alternatives, budget);
    }
}

}  // namespace

void run_baselines(ModelRun& run, SweepOutput& out, SweepReport& report, const SweepVariant& first) {
    const SweepConfig& config = run.config;
    auto one_slot = [](RenderMode, std::size_t, std::size_t) { return 0; };
    // The triangles of `level` of the first variant, as its first row says.
    auto triangles_of_level = [&](int level) {
        return triangles_of_row(out.results.rows.at(
            csv_row({run.entry.name, level_mode_name(first.mode), box_kind_name(first.box),
                     interpolation_name(first.interpolation), std::to_string(level), config.views[0],
                     format_number(config.distances[0]), render_mode_name(config.render_modes[0])})));
    };
    for (const EnumEntry<Baseline>& entry : baselines()) {  // in the table's order, whatever the config's
        const Baseline baseline = entry.value;
        const std::string name = entry.name;
        if (std::find(config.baselines.begin(), config.baselines.end(), baseline) == config.baselines.end())
            continue;
        const std::string top_group =
            csv_row({run.entry.name, name, "-", "-", std::to_string(first.obtained_levels)});
        if (baseline == Baseline::single_box) {
            run_group(run, out, report, top_group, one_slot, [&](int, int) {
                return candidate(single_box_model(run.model, run.threads), {}, 0, first.obtained_levels);
            });
            continue;
        }
        if (baseline == Baseline::impostor || baseline == Baseline::file_lods ||
            baseline == Baseline::proxy_baked) {  // their own groups
            if (baseline == Baseline::impostor)
                run_impostor(run, out, report, top_group, first.obtained_levels);
            else if (baseline == Baseline::proxy_baked)
                run_proxy_baked(run, out, report, first, triangles_of_level);
            else
                run_file_lods(run, out, report, first.obtained_levels);
            continue;
        }
        run_simplification(run, out, report, first, baseline, triangles_of_level);
    }
}

}  // namespace boxlod
