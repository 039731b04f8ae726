#include "toolkit/lod/level_faces.h"

#include "base/memory_budget.h"
#include "base/parallel.h"
#include "toolkit/lod/hybrid/baked_proxy.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>
#include <set>

namespace boxlod {
namespace {

// The quad of a face's `region` of its `texels` (the whole face for untextured
// boxes): TL, BL, BR, TR seen from outside; uvs into the region's atlas block.
void append_face_quad(Primitive& p, const OrientedBoxFace& f, const Eigen::Vector2i& texels,
                      const TexelRect& region, const AtlasPlacement* at, const Eigen::Vector2i& page) {
    auto base = std::uint32_t(p.positions.size());
    const int corners[4][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // (right, down) in the region
    for (const auto& c : corners) {
        // The corner in face texels (x right, y down), and as -1..1 along tangent and bitangent.
        const int x = region.x + c[0] * region.width, y = region.y + c[1] * region.height;
        const float s = 2 * (float(x) / float(texels.x())) - 1, t = 1 - 2 * (float(y) / float(texels.y()));
        p.positions.push_back(f.center + f.tangent * (s * f.half_width) + f.bitangent * (t * f.half_height));
        p.normals.push_back(f.normal);
        if (at) {
            p.uvs.push_back(
                page_uv(*at, region, page, float(c[0] * region.width), float(c[1] * region.height)));
            p.tangents.emplace_back(f.tangent.x(), f.tangent.y(), f.tangent.z(), 1.0f);
        }
    }
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    ++p.polygon_count;
}

// The texels of a face of box node n, sized at its texel scale (cut.h), and n's key in the bake cache.
Eigen::Vector2i texels_of(const OrientedBoxFace& face, const LodSession& session, const Cut& cut, int n) {
    return face_texels(2 * face.half_width, 2 * face.half_height,
                       coarser_sizing(session.derived.sizing, texel_scale(cut, n)));
}
std::pair<int, int> baked_key(const Cut& cut, int n) { return {n, texel_scale(cut, n)}; }

// The nodes whose box faces a level bakes: its box nodes, then its baked proxies' nodes.
std::vector<int> faced_nodes(const Cut& cut) {
    std::vector<int> nodes = cut.box_nodes;
    for (const BakedNode& baked : cut.baked_nodes) nodes.push_back(baked.node);
    return nodes;
}

// Where a packed face lands: its block's placement (flat faces: the swatches') and the page's size.
struct Landing {
    const AtlasPlacement* at;
    Eigen::Vector2i page;
};
Landing landing(const PackedFace& face, const Packing& packing, const Atlas& atlas) {
    const AtlasPlacement& at =
        atlas.placements[std::size_t(face.placement < 0 ? packing.swatch_placement : face.placement)];
    return {&at, atlas.pages[std::size_t(at.page)]};
}

// The uv of a flat face's swatch centre: bilinear reads its 2x2 middle texels, all one colour.
Eigen::Vector2f swatch_center(const PackedFace& face, const Packing& packing, const Landing& to) {
    const Eigen::Vector2i texel = swatch_texel(packing.swatches, *to.at, face.swatch);
    return {float(texel.x() + swatch_side / 2) / float(to.page.x()),
            float(texel.y() + swatch_side / 2) / float(to.page.y())};
}

// The swatch drawing `color`, added if new; none when the swatches are full (the face keeps its texels).
std::optional<int> swatch_of(Swatches& swatches, const std::array<std::uint8_t, 4>& color,
                             std::size_t max_swatches) {
    if (auto known = swatches.index.find(color); known != swatches.index.end()) return known->second;
    if (swatches.colors.size() >= max_swatches) return std::nullopt;
    swatches.index.emplace(color, int(swatches.colors.size()));
    swatches.colors.push_back(color);
    return int(swatches.colors.size()) - 1;
}

// Bytes a texel of a baked face or of a page holds: colour 4, normal 3, height 2 (docs/design.md: Errors).
constexpr double texel_bytes = 9;
// A level's pages are held about 2.5 times: as made and in the level's model as written (measured: the house
// at one 8192 x 8192 page peaked at 1.49 GB, its pages 604 MB; at --distance 0.001, 2.95 GB against 3.0).
constexpr double page_copies = 2.5;

// What the session's baked faces hold (kept for every later level).
double baked_bytes(const LodSession& session) {
    double texels = 0;
    for (const auto& [key, faces] : session.cache.baked)
        for (const BakedFace& face : faces) texels += double(face.height.pixels.size());
    return texel_bytes * texels;
}

double page_bytes(const Atlas& atlas) {
    double texels = 0;
    for (const Eigen::Vector2i& page : atlas.pages) texels += double(page.x()) * double(page.y());
    return texel_bytes * texels;
}

}  // namespace

void bake_new_faces(LodSession& session, const Cut& cut, int threads) {
    struct FaceJob {
        int node, face;
    };
    std::vector<FaceJob> jobs;
    std::set<std::pair<int, int>> new_keys;
    std::vector<double> texels;  // each new face's
    const LodDerived& d = session.derived;
    for (int node : faced_nodes(cut)) {
        if (session.cache.baked.count(baked_key(cut, node)) || !new_keys.insert(baked_key(cut, node)).second)
            continue;
        const std::array<OrientedBoxFace, 6> faces = oriented_box_faces(*d.boxes[node]);
        for (int f = 0; f < 6; ++f) {
            jobs.push_back({node, f});
            const Eigen::Vector2i size = texels_of(faces[std::size_t(f)], session, cut, node);
            texels.push_back(double(size.x()) * double(size.y()));
        }
    }
    // The faces, and a frame (renderer.h: make_frame, 32 bytes a pixel) for each worker's face, the largest
    // at once at worst, beside what is held (the faces baked before); checked before any slot is made, so
    // that a viewer showing the refusal keeps a whole cache.
    double bytes = texel_bytes * std::accumulate(texels.begin(), texels.end(), 0.0);
    const std::size_t workers = std::min(std::size_t(thread_count(threads)), texels.size());
    std::partial_sort(texels.begin(), texels.begin() + std::ptrdiff_t(workers), texels.end(),
                      std::greater<>());
    bytes += 32 * std::accumulate(texels.begin(), texels.begin() + std::ptrdiff_t(workers), 0.0);
    check_memory(session.input.model->source + ": its LoD's baked faces", bytes);
    for (const auto& key : new_keys)
        session.cache.baked.try_emplace(key);  // the slots made before the parallel work
    try {
        std::map<int, Drawable> subtrees;
        for (const FaceJob& job : jobs)
            if (job.face == 0)
                subtrees.emplace(job.node, make_drawable(*session.input.model, d.textures, job.node));
        parallel_for(jobs.size(), threads, [&](std::size_t j) {
            const FaceJob& job = jobs[j];
            OrientedBoxFace face = oriented_box_faces(*d.boxes[job.node])[job.face];
            session.cache.baked.at(baked_key(cut, job.node))[job.face] =
                bake_face(subtrees.at(job.node), face, texels_of(face, session, cut, job.node), 1);
        });
    } catch (...) {  // no slot left half baked for a later level to take as done
        for (const auto& key : new_keys) session.cache.baked.erase(key);
        session.cache.baked_held.set(baked_bytes(session));
        throw;
    }
    session.cache.baked_held.set(baked_bytes(session));
}

void check_pages_memory(const LodSession& session, const Atlas& atlas) {
    check_memory(session.input.model->source + ": its LoD's atlas pages", page_copies * page_bytes(atlas));
}

// Once made, a level's pages are held once, in its model.
std::shared_ptr<const MemoryHold> hold_pages(const Atlas& atlas) {
    return std::make_shared<const MemoryHold>(page_bytes(atlas));
}

Packing pack_faces(const LodSession& session, const Cut& cut, bool textured, int flat_faces, int threads) {
    const LodParameters& p = session.input.parameters;
    Packing packing;
    for (const BakedNode& node : cut.baked_nodes) {
        const std::array<BakedFace, 6>& baked = session.cache.baked.at(baked_key(cut, node.node));
        packing.proxy_faces[node.node] =
            baked_proxy_faces(*node.geometry, *session.derived.boxes[node.node], face_pointers(baked));
    }
    std::vector<Eigen::Vector2i> sizes;
    const int most_columns =
        (p.max_texture_size - 3) / swatch_side;  // the swatches' block fits the largest page
    const std::size_t max_swatches = std::size_t(most_columns) * std::size_t(most_columns);
    for (int node : faced_nodes(cut)) {
        const std::array<OrientedBoxFace, 6> faces = oriented_box_faces(*session.derived.boxes[node]);
        const auto proxy = packing.proxy_faces.find(node);
        for (int f = 0; f < 6; ++f) {
            if (proxy != packing.proxy_faces.end() && proxy->second[std::size_t(f)].indices.empty()) continue;
            const OrientedBoxFace& face = faces[f];
            const float scale =
                float(texel_scale(cut, node));  // a coarser box reaches the largest page 1:1 nearer
            packing.longest_face =
                std::max({packing.longest_face, 2 * face.half_width / scale, 2 * face.half_height / scale});
            if (!textured) continue;
            const Eigen::Vector2i texels = texels_of(face, session, cut, node);
            const BakedFace& baked = session.cache.baked.at(baked_key(cut, node))[f];
            const TexelRect region = p.crop_faces ? baked.covered : TexelRect{0, 0, texels.x(), texels.y()};
            if (region.empty()) continue;
            packing.height_depth = std::max(packing.height_depth, 2 * face.half_depth);
            packing.face_index[{node, f}] = packing.faces.size();
            const auto color = flat_faces > 0 ? flat_color(baked, region, flat_faces) : std::nullopt;
            if (const auto swatch =
                    color ? swatch_of(packing.swatches, *color, max_swatches) : std::nullopt) {
                packing.faces.push_back({node, f, region, -1, *swatch, texels});
                ++packing.flat_faces;
                continue;
            }
            packing.faces.push_back({node, f, region, int(sizes.size()), -1, texels});
            sizes.emplace_back(region.width, region.height);
            packing.face_texels += std::uint64_t(region.width) * std::uint64_t(region.height);
        }
    }
    if (Swatches& swatches = packing.swatches; !swatches.colors.empty()) {
        swatches.columns = int(std::ceil(std::sqrt(double(swatches.colors.size()))));
        packing.swatch_placement = int(sizes.size());
        sizes.emplace_back(swatches.block_side(), swatches.block_side());  // square: never turned
        packing.face_texels += std::uint64_t(swatch_side * swatch_side) * swatches.colors.size();
    }
    if (textured) {
        packing.atlas =
            pack_atlas(sizes, p.min_texture_size, p.max_texture_size, session.derived.sizing.gutter, threads);
        packing.gutter_texels = gutter_texels(packing.atlas, sizes, session.derived.sizing.gutter);
        if (packing.height_depth == 0)
            packing.height_depth = 1;  // flat boxes only: every height is 1, any depth is right
    }
    return packing;
}

void place_packed_faces(const LodSession& session, const Cut& cut, const Packing& packing, const Atlas& atlas,
                        Model& out) {
    for (const PackedFace& face : packing.faces) {
        if (face.placement < 0) continue;
        const AtlasPlacement& at = atlas.placements[std::size_t(face.placement)];
        const OrientedBoxFace box_face =
            oriented_box_faces(*session.derived.boxes[face.node])[std::size_t(face.face)];
        const LodPage page = lod_page(at.page);
        place_face(session.cache.baked.at(baked_key(cut, face.node))[std::size_t(face.face)], face.region, at,
                   session.derived.sizing.gutter, 2 * box_face.half_depth / packing.height_depth,
                   out.textures[std::size_t(page.color)], out.textures[std::size_t(page.normal)],
                   out.textures[std::size_t(page.height)]);
    }
}

std::map<int, Primitive> box_primitives(const LodSession& session, const Cut& cut, int n,
                                        const Packing& packing, const Atlas& atlas, bool textured) {
    std::map<int, Primitive> by_page;
    std::array<OrientedBoxFace, 6> faces = oriented_box_faces(*session.derived.boxes[n]);
    for (int f = 0; f < 6; ++f) {
        if (!textured) {
            Primitive& primitive = by_page[0];
            primitive.material = 0;
            append_face_quad(primitive, faces[f], {1, 1}, {0, 0, 1, 1}, nullptr, Eigen::Vector2i::Zero());
            continue;
        }
        const auto packed = packing.face_index.find({n, f});
        if (packed == packing.face_index.end()) continue;
        const PackedFace& face = packing.faces[packed->second];
        const Landing to = landing(face, packing, atlas);
        Primitive& primitive = by_page[to.at->page];
        primitive.material = to.at->page;
        append_face_quad(primitive, faces[f], texels_of(faces[f], session, cut, n), face.region, to.at,
                         to.page);
        if (face.placement < 0)
            std::fill(primitive.uvs.end() - 4, primitive.uvs.end(), swatch_center(face, packing, to));
    }
    return by_page;
}

std::map<int, Primitive> baked_primitives(int n, const Packing& packing, const Atlas& atlas,
                                          std::map<int, int>& made, Model& out) {
    std::map<int, Primitive> by_page;
    const std::array<Primitive, 6>& triangles = packing.proxy_faces.at(n);
    for (int f = 0; f < 6; ++f) {
        const auto packed = packing.face_index.find({n, f});
        if (packed == packing.face_index.end()) continue;  // no triangle samples it, or it saw nothing
        const PackedFace& face = packing.faces[packed->second];
        const Landing to = landing(face, packing, atlas);
        const Primitive& source = triangles[std::size_t(f)];
        Primitive& primitive = by_page[to.at->page];
        primitive.material = baked_page_material(out, to.at->page, made);
        const auto base = std::uint32_t(primitive.positions.size());
        for (std::size_t v = 0; v < source.positions.size(); ++v) {
            primitive.positions.push_back(source.positions[v]);
            primitive.normals.push_back(source.normals[v]);
            primitive.tangents.push_back(source.tangents[v]);
            if (face.placement < 0) {
                primitive.uvs.push_back(swatch_center(face, packing, to));
                continue;
            }
            // The face uv in texels of its region, kept inside it: the gutter holds the face's own texels
            // beyond.
            const Eigen::Vector2f uv = source.uvs[v];
            const TexelRect& region = face.region;
            const float x =
                std::clamp(uv.x() * float(face.texels.x()) - float(region.x), 0.0f, float(region.width));
            const float y =
                std::clamp(uv.y() * float(face.texels.y()) - float(region.y), 0.0f, float(region.height));
            primitive.uvs.push_back(page_uv(*to.at, region, to.page, x, y));
        }
        for (std::uint32_t index : source.indices) primitive.indices.push_back(base + index);
        primitive.polygon_count += source.polygon_count;
    }
    return by_page;
}

}  // namespace boxlod
