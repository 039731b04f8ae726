// A level's texture pages (docs/design.md: Atlas): one material per atlas
// page with its colour, normal and height textures, baked faces copied in
// with their gutters, and faces drawn flat from 4x4 swatches of one colour.
#pragma once
#include "toolkit/lod/pages/atlas.h"
#include "toolkit/lod/pages/bake.h"
#include "toolkit/model/model.h"

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace boxlod {

// The textures of atlas page K in an LoD's model: its colour, normal and
// height maps (color_K.png, normal_K.png, height_K.png); material K draws it.
struct LodPage {
    int color, normal, height;  // indices into Model::textures
};
LodPage lod_page(int page);

// A baked proxy's material on page K (baked_proxy.h), made on first use
// (`made`: page -> material): the page's colour and normal maps, opaque (its
// triangles give the outline, not the coverage), no height map (parallax
// would move its triangles off the surface they stand for).
int baked_page_material(Model& out, int page, std::map<int, int>& made);

// Where a point `x`, `y` texels into a face's region (right, down) lies on its page, as a uv.
Eigen::Vector2f page_uv(const AtlasPlacement& at, const TexelRect& region, const Eigen::Vector2i& page,
                        float x, float y);

// Flat faces (docs/design.md: Atlas): one 4x4 swatch per distinct colour, in
// one square block of the atlas whose swatches lie on 4-texel boundaries of
// the page (one GPU compression block each); 3 spare texels per side find them.
constexpr int swatch_side = 4;

struct Swatches {
    std::vector<std::array<std::uint8_t, 4>> colors;   // sRGB RGBA, opaque
    std::map<std::array<std::uint8_t, 4>, int> index;  // of each colour in `colors`
    int columns = 0;
    int block_side() const { return swatch_side * columns + swatch_side - 1; }
};

// One material per atlas page with its three empty textures (uncovered
// texels: transparent colour, the flat normal, height 0); untextured, one grey material.
void add_pages(Model& out, const Atlas& atlas, float height_depth, bool textured);

// The swatches into their block (placed at `at`) and its gutter: each texel takes the nearest
// swatch's colour, the flat normal and height 1 (a flat face lies on its box).
void place_swatches(const Swatches& swatches, const AtlasPlacement& at, int gutter, Model& out);

// A face `region` small enough for `flat_faces` and at least half covered gets
// its covered texels' mean colour, averaged in linear light as mip-maps are.
std::optional<std::array<std::uint8_t, 4>> flat_color(const BakedFace& face, const TexelRect& region,
                                                      int flat_faces);

// The page texel where swatch k starts, in the block placed at `at`.
Eigen::Vector2i swatch_texel(const Swatches& swatches, const AtlasPlacement& at, int k);

// Copies the `region` of a baked face into a page with its gutter: the face's
// own texels around the region where it has them (so a cropped face samples
// the neighbours it had uncropped), its edge texels repeated beyond; clipped
// to the page's border. Heights go from the face's own depth (0 at the box's
// opposite face) to the pages' common depth: depth_ratio = face depth / page depth.
void place_face(const BakedFace& face, const TexelRect& region, const AtlasPlacement& at, int gutter,
                float depth_ratio, Texture& color, Texture& normal, Texture& height);

}  // namespace boxlod
