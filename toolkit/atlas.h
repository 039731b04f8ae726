// Packing face textures into LoD texture pages (DESIGN.md: Atlas; the
// manual's Texture Coordinates section): square power-of-two pages, all of one
// size, starting at min_texture_size and doubling while more than one page is
// needed; at max_texture_size as many pages as needed. Deterministic.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace boxlod {

struct AtlasPlacement {
    int page = 0;
    int x = 0, y = 0;  // top-left texel of the face itself (the gutter lies around it)
};

struct Atlas {
    int page_size = 0;
    int pages = 0;
    std::vector<AtlasPlacement> placements;  // one per face, in input order
};

// `gutter` free texels around each face on every side (so >= 2 gutter between faces).
Atlas pack_atlas(const std::vector<Eigen::Vector2i>& face_sizes, int min_texture_size, int max_texture_size, int gutter);

}  // namespace boxlod
