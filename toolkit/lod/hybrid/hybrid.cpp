#include "toolkit/lod/hybrid/hybrid.h"

#include "base/parallel.h"
#include "toolkit/lod/cut/kept_subtrees.h"
#include "toolkit/lod/cut/level_budgets.h"
#include "toolkit/lod/hybrid/baked_proxy.h"
#include "toolkit/lod/hybrid/hybrid_measuring.h"
#include "toolkit/lod/hybrid/hybrid_order.h"
#include "toolkit/lod/hybrid/paid_textures.h"
#include "toolkit/lod/hybrid/proxy_drawables.h"
#include "toolkit/lod/hybrid/simplification.h"
#include "toolkit/lod/pages/bake.h"
#include "toolkit/model/framing.h"
#include "toolkit/model/model_subtree.h"
#include "toolkit/model/vertex_layout.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace boxlod {
namespace {

// The sub-tree simplified to these shares of its triangles: error targets
// from slight to coarse, each half the one before. Without the half, a level
// within a quarter of a building's bytes fell back to the eighth (docs/cost.md:
// The hybrid level mode).
constexpr std::array<double, 7> simplified_shares = {1, 0.5, 0.25, 0.125, 1.0 / 16, 1.0 / 32, 1.0 / 64};
// Large sub-trees by edge collapse also at 1/sqrt(2) and 1/sqrt(8): a budget
// between two halvings otherwise draws the coarser one
// (docs/cost.md: The hybrid level mode).
constexpr std::array<double, 9> large_simplified_shares = {1,     0.7071,   0.5,      0.3536,  0.25,
                                                           0.125, 1.0 / 16, 1.0 / 32, 1.0 / 64};
// The whole model (the root) is simplified at every 2^(-1/4) of its
// triangles from 1 down, by edge collapse and by clustering: where a level is
// the whole model simplified, a budget between two of the sub-trees' shares
// drew the coarser (DH_01_subs within 10 %: 71 % of its budget, 90 % now;
// docs/cost.md: Each budget at equal bytes). The
// steps of an octave as literals, so every libm gives the same shares.
constexpr std::array<double, 4> whole_model_octave = {1, 0.8408964152537145, 0.7071067811865476,
                                                      0.5946035575013605};
constexpr int subtree_octaves = 6;  // simplified_shares' last is 2^-6
// Below that the whole model goes on, at most 8 octaves more (to 1/16384: a
// building of 100,000 triangles to 6) and down to
// fewest_whole_model_triangles: the farthest levels, a few tenths of a percent
// of a building's bytes, draw it as one small mesh rather than one box; on
// every large sub-tree such shares won no more (docs/cost.md: Baked proxies).
// There an octave of shares in a row no simpler than the last ends them.
constexpr int most_whole_model_octaves = 8;
// A sub-tree's simplified proxies are measured only if a quarter of its
// triangles is enough to simplify to: the many smaller sub-trees cost most of
// the measuring and are rarely worth their own proxy (docs/cost.md: The hybrid level mode).
constexpr double smallest_simplified_share_of_interest = 0.25;
constexpr std::size_t fewest_simplified_triangles = 4;
// The whole model goes on to a single triangle: a small building's budget
// of 1 or 2 % (a CityJSON house of 148 triangles: 43 to 87 bytes) otherwise
// fits no level of hybrid's while simplification draws it in one or two.
constexpr std::size_t fewest_whole_model_triangles = 1;
// A sub-tree of at least this many triangles is also simplified by vertex
// clustering (meshopt_simplifySloppy), at every share below 1: a whole
// building's many separate parts cluster together where edge collapse
// stalls on each; on small sub-trees it costs measuring time and seldom wins
// (docs/cost.md: The hybrid level mode).
constexpr std::size_t fewest_clustered_triangles = 1000;
// A baked proxy's geometry at these shares of its sub-tree's triangles (baked_geometry).
// At 1, the geometry as it is: a textured low-poly building (3DBAG's) then
// keeps its shape and draws its texture re-baked at the level's texels, where
// a simplified one loses the roof's ridges (docs/cost.md: Baked proxies).
constexpr std::array<double, 4> baked_shares = {1, 0.25, 1.0 / 16, 1.0 / 64};
// A box is also offered with texels 2, 4, 8 and 16 times as large as the
// sizing distance gives them: a page is dear, and under a small budget several
// blurred boxes draw more than one sharp one. A coarser box is offered only
// where it costs at most 3/4 of the last one offered: most save a few bytes of
// pages at their least size, not worth measuring (docs/cost.md: The hybrid level mode).
constexpr std::array<int, 5> box_texel_scales = {1, 2, 4, 8, 16};
// Baked proxies at the box's texel scales 1, 4 and 16 (those offered), as the
// proxy-baked baseline: at all five they cost a fifth more planning time for no
// more cells won (docs/cost.md: Baked proxies).
constexpr std::array<int, 3> baked_texel_scales = {1, 4, 16};
constexpr double coarser_box_most_bytes = 0.75;

MeasuringView measuring_view(const Bounds& bounds, const HybridSettings& settings) {
    MeasuringView view;
    view.sphere = framing_of(bounds);
    const float diameter = 2 * view.sphere.radius;
    view.pixel = std::max(float(pixel_world_size(settings.sizing)), diameter / float(settings.max_side));
    view.side = std::clamp(int(std::ceil(diameter / view.pixel)), 1, settings.max_side);
    return view;
}

// A sub-tree simplified to one of simplified_shares, and the error sums it
// was measured with, per measuring view.
struct SimplifiedSubtree {
    std::vector<Primitive> primitives;
    std::size_t triangles = 0;
    bool clustered = false;
};

// A baked proxy as measured: its error sum, its mesh's bytes and the faces it samples.
struct BakedSum {
    double sum = 0;
    std::uint64_t mesh_bytes = 0;
    std::array<bool, 6> sampled{};
};

struct NodeMeasurement {
    bool simplified_made = false, baked_made = false;
    std::vector<SimplifiedSubtree>
        simplified;  // by edge collapse, then clustering: each simpler than the one before, in share order
    std::vector<SimplifiedSubtree> baked;  // baked proxies' geometry (baked_geometry)
    float pixel = 0;                       // the measuring view the sums below are of (0: none yet)
    int side = 0;
    std::map<float, double> box_sums;                   // per texel size (m) of the baked box
    std::map<float, std::vector<BakedSum>> baked_sums;  // per texel size, per geometry in `baked`
    bool simplified_measured = false;
    std::vector<double>
        simplified_sums;  // per simplified sub-tree; 0 for one of the sub-tree's own triangle count
};

}  // namespace

struct HybridMeasurements {
    std::vector<NodeMeasurement> nodes;
};

std::shared_ptr<HybridMeasurements> make_hybrid_measurements(const Model& model) {
    auto measurements = std::make_shared<HybridMeasurements>();
    measurements->nodes.resize(model.nodes.size());
    return measurements;
}

namespace {

// Pixels of the sizing view that differ: the measuring pixels' errors, each
// weighing (measuring pixel / sizing pixel)^2, mean over the directions.
double measured_error(double pixel_error_sum, const MeasuringView& view, const HybridSettings& settings) {
    const double scale = double(view.pixel) / pixel_world_size(settings.sizing);
    return pixel_error_sum * scale * scale / measuring_directions;
}

std::size_t triangle_count(const std::vector<Primitive>& primitives) {
    std::size_t triangles = 0;
    for (const Primitive& p : primitives) triangles += p.triangle_count();
    return triangles;
}

// The shares node n is simplified to (edge collapse or clustering).
constexpr std::size_t whole_model_common_shares = subtree_octaves * whole_model_octave.size() + 1;
std::vector<double> subtree_shares(int n, std::size_t subtree_triangles, bool clustering) {
    std::vector<double> shares;
    if (n == 0) {
        const int octaves = subtree_octaves + most_whole_model_octaves;
        for (int octave = 0; octave < octaves; ++octave)
            for (const double step : whole_model_octave) shares.push_back(step / double(1u << octave));
        shares.push_back(1 / double(1u << octaves));
        return shares;
    }
    const bool finer = subtree_triangles >= fewest_clustered_triangles && !clustering;
    if (finer) return {large_simplified_shares.begin(), large_simplified_shares.end()};
    return {simplified_shares.begin(), simplified_shares.end()};
}

// Node n's simplified sub-trees, each simpler than the one before (made once per model).
const std::vector<SimplifiedSubtree>& simplified_subtrees(const Model& model, int n,
                                                          std::size_t subtree_triangles,
                                                          NodeMeasurement& measurement) {
    if (measurement.simplified_made) return measurement.simplified;
    SimplifyOptions options;
    options.budget_by_area = true;  // walls keep their few triangles (docs/sweeps.md: simplification-best)
    options.threads = 1;
    for (const bool clustering : {false, true}) {
        if (clustering && subtree_triangles < fewest_clustered_triangles) break;
        options.edge_collapse = !clustering;
        std::size_t previous = subtree_triangles + 1;
        const std::vector<double> shares = subtree_shares(n, subtree_triangles, clustering);
        const std::size_t common = n == 0 ? whole_model_common_shares : shares.size();
        int stalls = 0;
        for (std::size_t k = 0; k < shares.size(); ++k) {
            const double share = shares[k];
            const auto target = std::size_t(double(subtree_triangles) * share);
            if (target < (n == 0 ? fewest_whole_model_triangles : fewest_simplified_triangles)) break;
            if (clustering && share == 1) continue;  // at 1 only merged and welded, as without clustering
            SimplifiedSubtree simplified{simplify_subtree(model, n, target, options), 0, clustering};
            simplified.triangles = triangle_count(simplified.primitives);
            if (simplified.triangles == 0 || simplified.triangles >= previous) {
                // Past 1/64 an octave of stalls ends the whole model's shares: the next would stall as well.
                if (k >= common && ++stalls == int(whole_model_octave.size())) break;
                continue;  // nothing left, or no simpler than the last
            }
            stalls = 0;
            previous = simplified.triangles;
            measurement.simplified.push_back(std::move(simplified));
        }
    }
    measurement.simplified_made = true;
    return measurement.simplified;
}

// The geometry of node n's baked proxies (baked_proxy.h; made once per
// model): its sub-tree as one mesh of positions, as it is and simplified
// across material seams to 1/4, 1/16 and 1/64 of its triangles by edge
// collapse (the whole model on down by quarters, to simplified_subtrees' floor), and for large sub-trees by
// clustering too (but at 1). Baking is for far levels, where a box would lose the silhouette and
// simplification the colours.
const std::vector<SimplifiedSubtree>& baked_geometry(const Model& model, int n, std::size_t subtree_triangles,
                                                     NodeMeasurement& measurement) {
    if (measurement.baked_made) return measurement.baked;
    SimplifyOptions options;
    options.geometry_only = true;
    options.threads = 1;
    std::vector<double> shares(baked_shares.begin(), baked_shares.end());
    if (n == 0)
        for (int k = 0; k < most_whole_model_octaves / 2; ++k) shares.push_back(shares.back() / 4);
    const std::size_t fewest = n == 0 ? fewest_whole_model_triangles : fewest_simplified_triangles;
    for (const bool clustering : {false, true}) {
        if (clustering && subtree_triangles < fewest_clustered_triangles) break;
        options.edge_collapse = !clustering;
        std::size_t previous = subtree_triangles + 1;
        for (std::size_t k = 0; k < shares.size(); ++k) {
            const auto target = std::size_t(double(subtree_triangles) * shares[k]);
            if (target < fewest) break;
            if (clustering && shares[k] == 1) continue;  // as it is: once
            SimplifiedSubtree simplified{simplify_subtree(model, n, target, options), 0, clustering};
            simplified.triangles = triangle_count(simplified.primitives);
            if (simplified.triangles == 0 || simplified.triangles >= previous) {
                if (k >= baked_shares.size()) break;  // the whole model's further shares would stall as well
                continue;
            }
            previous = simplified.triangles;
            measurement.baked.push_back(std::move(simplified));
        }
    }
    measurement.baked_made = true;
    return measurement.baked;
}

// A box's texels: their size in metres (as measurements are kept) and the sizing that bakes them.
struct BoxTexels {
    float size = 0;
    TextureSizing sizing;
    int scale = 1;  // box_texel_scales'
};

// Among its siblings: the parent's sub-tree but n's own, drawn in every
// measuring render; only what those can see, within 2 radii of the centre
// (camera at 2r, view r wide).
std::vector<const Primitive*> sibling_primitives(const Model& model, int n, const MeasuringView& view) {
    std::vector<const Primitive*> others;
    const int parent = model.nodes[std::size_t(n)].parent;
    if (parent < 0) return others;
    std::vector<bool> mine(model.nodes.size(), false);
    for (int k : subtree_nodes(model, n)) mine[std::size_t(k)] = true;
    const Eigen::Vector3f center = view.sphere.center;
    const float reach = 2 * view.sphere.radius;
    for (int k : subtree_nodes(model, parent))
        if (!mine[std::size_t(k)])
            for (const Primitive& p : model.nodes[std::size_t(k)].primitives) {
                Eigen::AlignedBox3f bounds;
                for (const Eigen::Vector3f& v : p.positions) bounds.extend(v);
                if (!p.positions.empty() && bounds.squaredExteriorDistance(center) <= reach * reach)
                    others.push_back(&p);
            }
    return others;
}

// Baked proxies are offered where asked for, the levels are textured (they draw their box's pages) and
// the box is at one of baked_texel_scales.
bool baked_wanted(const HybridSettings& settings, int texel_scale) {
    return settings.baked_proxies && settings.mode != RenderMode::untextured &&
           std::find(baked_texel_scales.begin(), baked_texel_scales.end(), texel_scale) !=
               baked_texel_scales.end();
}

// What a node's candidates are drawn among: the rest of the model near it, in its materials' base
// colours, untextured: it only hides and is hidden, the same in every render. Its opaque part is
// rendered once per direction (`underlay`) and each candidate over it from its depth (renderer.h:
// depth_from_frame), its blended part with each candidate: the pictures of one render of the
// context and the candidate, at a fraction of the cost.
struct MeasuringContext {
    Drawable drawable;  // owns the meshes `blended` points into
    std::vector<Batch> blended;
    std::vector<Frame> underlay;
};

MeasuringContext measuring_context(const Model& model, int n, const MeasuringView& view, RenderMode mode) {
    std::vector<Material> plain = model.materials;
    for (Material& m : plain)
        m = Material{.name = m.name, .base_color = m.base_color, .alpha_mode = m.alpha_mode};
    MeasuringContext context{
        make_drawable(plain, DecodedTextures{}, sibling_primitives(model, n, view)), {}, {}};
    std::vector<Batch> opaque;
    for (const Batch& batch : context.drawable.batches)
        (batch.surface.alpha_mode == AlphaMode::blend ? context.blended : opaque).push_back(batch);
    context.underlay = render_views(opaque, view, mode, nullptr, false);
    return context;
}

// The error sums of node n's box at each of `box_texels` and of its
// simplified sub-trees in `view`, rendered among their siblings, but those
// `measurement` holds for this view.
void measure_error_sums(const Model& model, const DecodedTextures& textures, int n, const OrientedBox& box,
                        const std::vector<BoxTexels>& box_texels, std::size_t subtree_triangles,
                        const Drawable& subtree, const MeasuringView& view, const HybridSettings& settings,
                        NodeMeasurement& measurement) {
    if (measurement.pixel != view.pixel || measurement.side != view.side) {
        measurement.box_sums.clear();
        measurement.baked_sums.clear();
        measurement.simplified_sums.clear();
        measurement.simplified_measured = false;
        measurement.pixel = view.pixel;
        measurement.side = view.side;
    }
    std::vector<BoxTexels> missing;
    for (const BoxTexels& texels : box_texels)
        if (!measurement.box_sums.count(texels.size) ||
            (baked_wanted(settings, texels.scale) && !measurement.baked_sums.count(texels.size)))
            missing.push_back(texels);
    if (missing.empty() && measurement.simplified_measured) return;
    const MeasuringContext context = measuring_context(model, n, view, settings.mode);
    auto among_context = [&](const Drawable& d) {
        std::vector<Batch> batches = context.blended;
        batches.insert(batches.end(), d.batches.begin(), d.batches.end());
        return compared_views(render_views(batches, view, settings.mode, &context.underlay));
    };
    const auto original = among_context(subtree);
    const std::vector<SimplifiedSubtree>& simplified_list =
        simplified_subtrees(model, n, subtree_triangles, measurement);
    const bool textured = settings.mode != RenderMode::untextured;
    for (const BoxTexels& texels : missing) {
        const std::array<BakedFace, 6> baked =
            textured ? bake_box(subtree, box, texels.sizing) : std::array<BakedFace, 6>{};
        measurement.box_sums[texels.size] = pixel_error_sum(
            original, among_context(box_proxy_drawable(box, textured ? &baked : nullptr)->drawable));
        if (!baked_wanted(settings, texels.scale)) continue;
        std::vector<BakedSum>& baked_sums = measurement.baked_sums[texels.size];
        for (const SimplifiedSubtree& geometry : baked_geometry(model, n, subtree_triangles, measurement)) {
            std::array<Primitive, 6> faces =
                baked_proxy_faces(geometry.primitives, box, face_pointers(baked));
            BakedSum measured{0, baked_proxy_mesh_bytes(faces), {}};
            for (std::size_t f = 0; f < 6; ++f) measured.sampled[f] = !faces[f].indices.empty();
            measured.sum = pixel_error_sum(
                original, among_context(baked_proxy_drawable(std::move(faces), baked)->drawable));
            baked_sums.push_back(measured);
        }
    }
    if (measurement.simplified_measured) return;
    for (const SimplifiedSubtree& simplified : simplified_list) {
        double sum = 0;
        if (simplified.triangles <
            subtree_triangles) {  // else only merged and welded: the same triangles, nothing to measure
            std::vector<const Primitive*> primitives;
            for (const Primitive& p : simplified.primitives) primitives.push_back(&p);
            sum = pixel_error_sum(original,
                                  among_context(make_drawable(model.materials, textures, primitives)));
        }
        measurement.simplified_sums.push_back(sum);
    }
    measurement.simplified_measured = true;
}

// The baked proxies measured with its box at `texel_scale` (`sums`, per geometry in measurement.baked).
void add_baked_proxies(const OrientedBox& box, int texel_scale, const std::vector<BakedSum>& sums,
                       const NodeMeasurement& measurement, const MeasuringView& view,
                       const HybridSettings& settings, std::vector<Proxy>& proxies) {
    const std::array<OrientedBoxFace, 6> faces = oriented_box_faces(box);
    const TextureSizing sizing = coarser_sizing(settings.sizing, texel_scale);
    for (std::size_t c = 0; c < sums.size(); ++c) {
        if (sums[c].mesh_bytes == 0) continue;  // it samples no face that saw anything: it would draw nothing
        Proxy proxy;
        proxy.kind = ProxyKind::baked;
        proxy.primitives = measurement.baked[c].primitives;
        proxy.clustered = measurement.baked[c].clustered;
        proxy.texel_scale = texel_scale;
        std::uint64_t texels = 0;
        for (std::size_t f = 0; f < 6; ++f)
            if (sums[c].sampled[f]) texels += face_page_texels(faces[f], sizing);
        proxy.bytes = double(sums[c].mesh_bytes + page_bytes(texels));
        proxy.error = measured_error(sums[c].sum, view, settings);
        proxies.push_back(std::move(proxy));
    }
}

// Every proxy of node n, measured (or its measurements reused); then sorted by
// bytes drawn alone (with the textures they sample), keeping only those that
// beat every cheaper one and cost less than the sub-tree itself.
std::vector<Proxy> measure_proxies(const Model& model, const DecodedTextures& textures, int n,
                                   const OrientedBox& box, double subtree_bytes,
                                   std::size_t subtree_triangles, const PaidTextures& paid,
                                   const HybridSettings& settings) {
    const Drawable subtree = make_drawable(model, textures, n);
    const MeasuringView view = measuring_view(subtree.bounds, settings);
    // The box at each texel scale that saves bytes and whose texels the
    // measuring view can tell from the finest's (coarser than its pixel).
    // The finest is measured with texels of the measuring pixel's size.
    std::vector<Proxy> proxies;
    std::vector<BoxTexels> box_texels;
    const double pixel = pixel_world_size(settings.sizing);
    for (int scale : box_texel_scales) {
        Proxy box_proxy;
        box_proxy.texel_scale = scale;
        const TextureSizing sizing = coarser_sizing(settings.sizing, scale);
        box_proxy.bytes = double(box_bytes_estimate(box, sizing, settings.mode != RenderMode::untextured));
        if (scale > 1 && box_proxy.bytes > coarser_box_most_bytes * proxies.back().bytes) continue;
        const float texel = scale == 1 ? view.pixel : float(scale * pixel);  // the measurements' key
        if (scale > 1 && !(texel > view.pixel)) continue;
        box_texels.push_back(
            {texel, scale == 1 ? coarser_sizing(settings.sizing, double(view.pixel) / pixel) : sizing,
             scale});
        proxies.push_back(std::move(box_proxy));
    }
    NodeMeasurement own;
    NodeMeasurement& measurement = settings.measurements ? settings.measurements->nodes[std::size_t(n)] : own;
    measure_error_sums(model, textures, n, box, box_texels, subtree_triangles, subtree, view, settings,
                       measurement);
    for (std::size_t k = 0; k < proxies.size(); ++k)
        proxies[k].error = measured_error(measurement.box_sums.at(box_texels[k].size), view, settings);
    for (std::size_t k = 0; k < measurement.simplified.size(); ++k) {
        Proxy proxy;
        proxy.kind = ProxyKind::simplified;
        proxy.primitives = measurement.simplified[k].primitives;
        proxy.clustered = measurement.simplified[k].clustered;
        proxy.bytes = double(mesh_bytes(proxy.primitives, model));
        proxy.error = measured_error(measurement.simplified_sums[k], view, settings);
        proxies.push_back(std::move(proxy));
    }
    for (std::size_t k = 0; k < box_texels.size(); ++k)
        if (baked_wanted(settings, box_texels[k].scale))
            add_baked_proxies(box, proxies[k].texel_scale, measurement.baked_sums.at(box_texels[k].size),
                              measurement, view, settings, proxies);
    std::vector<std::pair<double, Proxy>> by_bytes;  // each with its bytes alone
    for (Proxy& proxy : proxies) {
        const double alone = proxy.bytes + bytes_of(paid, proxy_textures(paid, proxy));
        by_bytes.emplace_back(alone, std::move(proxy));
    }
    std::stable_sort(by_bytes.begin(), by_bytes.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Proxy> kept;
    for (auto& [alone, proxy] : by_bytes)
        if (alone < subtree_bytes && (kept.empty() || proxy.error < kept.back().error))
            kept.push_back(std::move(proxy));
    return kept;
}

// Per node, after the first `count` of `steps`: its proxy, or -1 where it keeps its geometry.
std::vector<int> state_after(const HybridPlan& plan, const std::vector<HybridStep>& steps,
                             std::size_t count) {
    std::vector<int> state(plan.proxies.size(), -1);
    for (std::size_t n = 0; n < plan.proxies.size(); ++n)
        if (!plan.proxies[n].empty()) state[n] = 0;
    for (std::size_t k = 0; k < std::min(count, steps.size()); ++k)
        state[std::size_t(steps[k].node)] = steps[k].proxy;
    return state;
}

}  // namespace

HybridPlan plan_hybrid(const Model& model, const DecodedTextures& textures,
                       const std::vector<std::optional<OrientedBox>>& boxes, const HybridSettings& settings) {
    HybridPlan plan;
    plan.proxies.resize(model.nodes.size());
    const bool textured = settings.mode != RenderMode::untextured;
    const std::vector<std::uint64_t> bytes = subtree_mesh_bytes(model);
    const std::vector<std::size_t> triangles = subtree_triangles(model);
    // A node is measured where some proxy may cost less than its sub-tree:
    // its coarsest box (than the sub-tree's mesh and the textures only it samples,
    // which the box may free; counting those that others sample too would
    // measure nodes no box can pay for), or a simplified sub-tree (enough triangles
    // for the first share that simplifies). Proxies are then kept by their
    // bytes alone, with every texture they sample.
    const PaidTextures paid = paid_textures(model);
    const std::vector<std::vector<int>> sampled = subtree_textures(model, paid),
                                        exclusive = exclusive_textures(model, paid);
    std::vector<double> alone(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        alone[n] = double(bytes[n]) + bytes_of(paid, sampled[n]);
    std::vector<int> measured;
    const TextureSizing coarsest = coarser_sizing(settings.sizing, box_texel_scales.back());
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (boxes[n] && (box_bytes_estimate(*boxes[n], coarsest, textured) <
                             double(bytes[n]) + bytes_of(paid, exclusive[n]) ||
                         double(triangles[n]) * smallest_simplified_share_of_interest >=
                             double(fewest_simplified_triangles)))
            measured.push_back(int(n));
    parallel_for(measured.size(), settings.threads, [&](std::size_t i) {
        const auto n = std::size_t(measured[i]);
        plan.proxies[n] =
            measure_proxies(model, textures, int(n), *boxes[n], alone[n], triangles[n], paid, settings);
    });
    order_hybrid_plan(model, plan);
    return plan;
}

void order_hybrid_plan(const Model& model, HybridPlan& plan) {
    plan.prices = plan_prices(model, plan.proxies);
    plan.steps.clear();
    plan.bytes.clear();
    plan.error.clear();
    order_within(model, plan.proxies, plan.prices, std::numeric_limits<double>::infinity(), plan.steps,
                 plan.bytes, plan.error);
}

std::vector<int> hybrid_state(const HybridPlan& plan, std::size_t steps) {
    return state_after(plan, plan.steps, steps);
}

HybridLevel hybrid_level_within(const Model& model, const HybridPlan& plan, double budget) {
    auto replay = [&](const std::vector<int>* start) {
        std::vector<HybridStep> steps;
        std::vector<double> bytes, error;
        order_within(model, plan.proxies, plan.prices, budget, steps, bytes, error, start);
        const std::size_t best = best_prefix_within(bytes, error, budget);
        return HybridLevel{state_after(plan, steps, best), bytes[best], error[best]};
    };
    // The greedy order can stall behind an opening that gains nothing until
    // its children change: also from the pruned cut within the budget, keeping
    // the one within the budget, else the lower error (docs/design.md: The hybrid level mode).
    HybridLevel greedy = replay(nullptr);
    const std::vector<int> start = pruned_state_within(model, plan.proxies, plan.prices, budget);
    HybridLevel pruned = replay(&start);
    auto fits = [&](const HybridLevel& level) { return level.bytes <= budget * (1 + 1e-12); };
    const bool take_pruned = fits(pruned) != fits(greedy) ? fits(pruned) : pruned.error < greedy.error;
    return take_pruned ? std::move(pruned) : std::move(greedy);
}

Cut hybrid_cut(const Model& model, const HybridPlan& plan, const std::vector<int>& state) {
    Cut cut;
    for (std::vector<int> stack{0}; !stack.empty();) {
        const int n = stack.back();
        stack.pop_back();
        const Node& node = model.nodes[std::size_t(n)];
        cut.used_nodes.push_back(n);
        if (const int s = state[std::size_t(n)]; s >= 0) {
            const Proxy& proxy = plan.proxies[std::size_t(n)][std::size_t(s)];
            if (proxy.kind == ProxyKind::simplified) cut.simplified_nodes.emplace_back(n, s);
            if (proxy.kind == ProxyKind::baked) cut.baked_nodes.push_back({n, s, &proxy.primitives});
            if (proxy.kind == ProxyKind::box) cut.box_nodes.push_back(n);
            if (proxy.kind != ProxyKind::simplified && proxy.texel_scale > 1)
                cut.box_texel_scales[n] = proxy.texel_scale;
            continue;
        }
        if (node.has_geometry()) cut.geometry_nodes.push_back(n);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back(*child);
    }
    return cut;
}

double hybrid_cut_error(const HybridPlan& plan, const Cut& cut) {
    double error = 0;
    for (int n : cut.box_nodes)
        for (const Proxy& proxy : plan.proxies[std::size_t(n)])
            if (proxy.kind == ProxyKind::box && proxy.texel_scale == texel_scale(cut, n))
                error += proxy.error;
    for (auto [n, proxy] : cut.simplified_nodes)
        error += plan.proxies[std::size_t(n)][std::size_t(proxy)].error;
    for (const BakedNode& baked : cut.baked_nodes)
        if (baked.proxy >= 0) error += plan.proxies[std::size_t(baked.node)][std::size_t(baked.proxy)].error;
    return error;
}

LevelValues hybrid_levels(const Model& model, const HybridPlan& plan, const std::vector<double>& budgets,
                          std::vector<HybridLevel>& levels) {
    const int count = int(budgets.size());
    LevelValues values;
    values.obtained_levels = count;
    values.level.assign(model.nodes.size(), 0);
    levels.assign(budgets.size() + 1, {std::vector<int>(model.nodes.size(), -1), plan.bytes.back(), 0});
    for (int c = count; c >= 1; --c) {
        levels[std::size_t(c)] = hybrid_level_within(model, plan, budgets[std::size_t(c - 1)]);
        for (int n : hybrid_cut(model, plan, levels[std::size_t(c)].state).geometry_nodes)
            values.level[std::size_t(n)] = std::max(values.level[std::size_t(n)], std::min(c, count - 1));
    }
    return values;
}

}  // namespace boxlod
