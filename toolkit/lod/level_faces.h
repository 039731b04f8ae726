// A level's box faces (docs/design.md: Baking, Atlas): the faces of its box
// nodes and of its baked proxies (cut.h), baked once per session, packed into
// the level's pages and copied in; a box draws them as one quad each, a baked
// proxy as its triangles that sample them (baked_proxy.h).
#pragma once
#include "toolkit/lod/cut/cut.h"
#include "toolkit/lod/lod_session.h"
#include "toolkit/lod/pages/level_pages.h"

#include <array>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace boxlod {

// A face that goes into the atlas with the rectangle of its texels it keeps:
// cropped to the covered ones, none for a face that covers nothing (unless
// crop_faces is off). A baked proxy's faces that none of its triangles sample are left out.
struct PackedFace {
    int node, face;
    TexelRect region;
    int placement = -1;  // its block in the atlas; -1: drawn flat from `swatch`
    int swatch = -1;
    Eigen::Vector2i texels = Eigen::Vector2i::Zero();  // the whole face's, as sized
};

struct Packing {
    std::vector<PackedFace> faces;  // box nodes' in cut order, then baked nodes', each in face order
    std::map<std::pair<int, int>, std::size_t> face_index;  // (node, face) -> its entry in `faces`
    std::map<int, std::array<Primitive, 6>>
        proxy_faces;  // per baked node, its triangles per face (baked_proxy_faces)
    Atlas atlas;
    Swatches swatches;
    int swatch_placement = -1;  // the swatches' block in the atlas
    std::uint64_t face_texels = 0, gutter_texels = 0;
    int flat_faces = 0;
    float longest_face = 0;  // metres over the texel scale, for min_distance
    float height_depth = 0;  // metres: the deepest packed face's box depth, height 0 on every page
};

// Bake: the faces of the cut's boxes and baked proxies that no earlier level baked, in parallel (one face per
// task).
void bake_new_faces(LodSession& session, const Cut& cut, int threads);

// The pages of `atlas` within the memory budget beside what is held: every session's baked faces and
// every level's pages (InputError naming the model); and the hold a level keeps for them once made.
void check_pages_memory(const LodSession& session, const Atlas& atlas);
std::shared_ptr<const MemoryHold> hold_pages(const Atlas& atlas);

// Pack: the kept rectangles of the cut's faces into pages; faces of at most `flat_faces` texels (0: none) as
// swatches.
Packing pack_faces(const LodSession& session, const Cut& cut, bool textured, int flat_faces, int threads);

// Copies each packed face's texels (not those drawn flat) into its page with its gutter.
void place_packed_faces(const LodSession& session, const Cut& cut, const Packing& packing, const Atlas& atlas,
                        Model& out);

// Box node n's quads, one primitive per page its faces landed on (material K draws page K).
std::map<int, Primitive> box_primitives(const LodSession& session, const Cut& cut, int n,
                                        const Packing& packing, const Atlas& atlas, bool textured);

// Baked node n's triangles, one primitive per page, each uv moved into its
// face's block; materials as baked_page_material makes them (`made`: per page, once).
std::map<int, Primitive> baked_primitives(int n, const Packing& packing, const Atlas& atlas,
                                          std::map<int, int>& made, Model& out);

}  // namespace boxlod
