#include "toolkit/atlas.h"

#include <stb_rect_pack.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace boxlod {
namespace {

// Packs as many of `faces` as fit into one page; returns the ones left over.
std::vector<int> pack_page(const std::vector<int>& faces, const std::vector<Eigen::Vector2i>& sizes, int page_size,
                           int gutter, int page, std::vector<AtlasPlacement>& placements) {
    std::vector<stbrp_node> nodes(static_cast<std::size_t>(page_size));
    stbrp_context context;
    stbrp_init_target(&context, page_size, page_size, nodes.data(), int(nodes.size()));
    std::vector<stbrp_rect> rects(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
        rects[i].id = int(i);
        rects[i].w = sizes[faces[i]].x() + 2 * gutter;
        rects[i].h = sizes[faces[i]].y() + 2 * gutter;
    }
    stbrp_pack_rects(&context, rects.data(), int(rects.size()));
    std::vector<int> left;
    for (const stbrp_rect& rect : rects) {  // stb keeps the input order on return
        int face = faces[rect.id];
        if (rect.was_packed) placements[face] = {page, rect.x + gutter, rect.y + gutter};
        else left.push_back(face);
    }
    return left;
}

}  // namespace

Atlas pack_atlas(const std::vector<Eigen::Vector2i>& sizes, int min_texture_size, int max_texture_size, int gutter) {
    Atlas atlas;
    atlas.placements.resize(sizes.size());
    for (const Eigen::Vector2i& s : sizes)
        if (s.x() + 2 * gutter > max_texture_size || s.y() + 2 * gutter > max_texture_size)
            throw std::invalid_argument("pack_atlas: a face is larger than the largest page");
    // Tallest first (ties: widest, then input order) packs tightly and never depends on anything else.
    std::vector<int> order(sizes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        if (sizes[a].y() != sizes[b].y()) return sizes[a].y() > sizes[b].y();
        return sizes[a].x() > sizes[b].x();
    });
    for (int size = min_texture_size;; size *= 2) {
        atlas.page_size = std::min(size, max_texture_size);
        bool at_max = atlas.page_size >= max_texture_size;
        bool fits = std::all_of(order.begin(), order.end(), [&](int face) {
            return sizes[face].x() + 2 * gutter <= atlas.page_size && sizes[face].y() + 2 * gutter <= atlas.page_size;
        });
        if (!fits) continue;
        atlas.pages = 0;
        std::vector<int> left = order;
        while (!left.empty() && (atlas.pages == 0 || at_max)) {
            left = pack_page(left, sizes, atlas.page_size, gutter, atlas.pages, atlas.placements);
            ++atlas.pages;
        }
        if (left.empty()) return atlas;  // one page, or the largest size with as many pages as needed
    }
}

}  // namespace boxlod
