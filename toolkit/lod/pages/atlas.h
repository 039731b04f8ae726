// Packing face textures into LoD texture pages (docs/design.md: Atlas; the manual's
// Texture Coordinates section). Pages are power-of-two width x height between
// min and max texture size: full pages at the largest size while what is left
// does not fit one, then the smallest page that holds the rest, split into
// smaller pages where that saves more than a tenth of its texels. A face may lie
// turned by 90 degrees where that packs tighter. Deterministic.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace boxlod {

struct AtlasPlacement {
    int page = 0;
    int x = 0, y = 0;  // top-left texel of the face's block in the page (the gutter lies around it)
    bool rotated =
        false;  // turned 90 degrees clockwise: the face's rows run down the page, its top row rightmost
};

struct Atlas {
    std::vector<Eigen::Vector2i> pages;      // each page's width x height
    std::vector<AtlasPlacement> placements;  // one per face, in input order
};

// `gutter` free texels around each face on every side (so >= 2 gutter between
// faces); none is needed at a page's border (the sampler clamps to the edge).
// Throws std::invalid_argument when a face does not fit max_texture_size.
Atlas pack_atlas(const std::vector<Eigen::Vector2i>& face_sizes, int min_texture_size, int max_texture_size,
                 int gutter, int threads = 1);

// The size of a face's block in its page: its texels, swapped when rotated.
Eigen::Vector2i placed_size(const Eigen::Vector2i& face_size, const AtlasPlacement& placement);

std::uint64_t page_texels(const Atlas& atlas);  // sum of width x height over the pages

// The gutter texels the faces' blocks take inside their pages (a block at the
// page's border has none beyond it): page texels = face texels + gutter texels + free texels.
std::uint64_t gutter_texels(const Atlas& atlas, const std::vector<Eigen::Vector2i>& face_sizes, int gutter);

}  // namespace boxlod
