#include "toolkit/lod/pages/atlas.h"

#include "base/parallel.h"

#include <stb_rect_pack.h>

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace boxlod {
namespace {

// A face's block as it will be packed: its size, turned or not.
struct Block {
    int face = 0;
    Eigen::Vector2i size;
    bool rotated = false;
};

// Packs as many blocks as fit into a width x height page (skyline, best fit);
// returns the ones left over. Blocks are padded by the gutter on every side and
// the page by the gutter around it, so faces may touch the page's border.
std::vector<Block> pack_page(const std::vector<Block>& blocks, Eigen::Vector2i page_size, int gutter,
                             int page, std::vector<AtlasPlacement>* placements) {
    const int width = page_size.x() + 2 * gutter, height = page_size.y() + 2 * gutter;
    std::vector<stbrp_node> nodes(static_cast<std::size_t>(width));
    stbrp_context context;
    stbrp_init_target(&context, width, height, nodes.data(), int(nodes.size()));
    stbrp_setup_heuristic(&context, STBRP_HEURISTIC_Skyline_BF_sortHeight);
    std::vector<stbrp_rect> rects(blocks.size());
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        rects[i].id = int(i);
        rects[i].w = blocks[i].size.x() + 2 * gutter;
        rects[i].h = blocks[i].size.y() + 2 * gutter;
    }
    stbrp_pack_rects(&context, rects.data(), int(rects.size()));
    std::vector<Block> left;
    for (const stbrp_rect& rect : rects) {  // stb keeps the input order on return
        const Block& block = blocks[std::size_t(rect.id)];
        if (!rect.was_packed)
            left.push_back(block);
        else if (placements)
            (*placements)[std::size_t(block.face)] = {page, rect.x, rect.y, block.rotated};
    }
    return left;
}

// Whether the blocks surely do not fit one page. Most pages tried are too
// small, which two necessary conditions tell without packing (four fifths of
// the tries when building `manual`'s levels): every block within the page's
// sides, and the padded blocks' area within the padded page's.
bool cannot_fit(const std::vector<Block>& blocks, Eigen::Vector2i page_size, int gutter) {
    std::uint64_t padded_area = 0;
    for (const Block& block : blocks) {
        if (block.size.x() > page_size.x() || block.size.y() > page_size.y()) return true;
        padded_area +=
            std::uint64_t(block.size.x() + 2 * gutter) * std::uint64_t(block.size.y() + 2 * gutter);
    }
    return padded_area >
           std::uint64_t(page_size.x() + 2 * gutter) * std::uint64_t(page_size.y() + 2 * gutter);
}

// `atlas` with all blocks on one more page of `page_size`, if they fit it.
std::optional<Atlas> with_page(const Atlas& atlas, const std::vector<Block>& blocks,
                               Eigen::Vector2i page_size, int gutter) {
    if (cannot_fit(blocks, page_size, gutter)) return std::nullopt;
    Atlas out = atlas;
    if (!pack_page(blocks, page_size, gutter, int(out.pages.size()), &out.placements).empty())
        return std::nullopt;
    out.pages.push_back(page_size);
    return out;
}

std::uint64_t area(Eigen::Vector2i size) { return std::uint64_t(size.x()) * std::uint64_t(size.y()); }

// Every power-of-two page size between the limits, smallest area first; of equal
// areas the squarer first, then the wider.
std::vector<Eigen::Vector2i> page_sizes(int min_texture_size, int max_texture_size) {
    std::vector<Eigen::Vector2i> sizes;
    for (int w = min_texture_size; w <= max_texture_size; w *= 2)
        for (int h = min_texture_size; h <= max_texture_size; h *= 2) sizes.emplace_back(w, h);
    std::stable_sort(sizes.begin(), sizes.end(), [](Eigen::Vector2i a, Eigen::Vector2i b) {
        if (area(a) != area(b)) return area(a) < area(b);
        if (std::abs(a.x() - a.y()) != std::abs(b.x() - b.y()))
            return std::abs(a.x() - a.y()) < std::abs(b.x() - b.y());
        return a.x() > b.x();
    });
    return sizes;
}

// Pages holding all of `left` that fits one page of the largest size: the
// smallest page holding it, or, when that page would be less than 90 % used, the
// largest page of smaller area filled first and the rest packed the same way;
// whichever has fewer texels, so a few more pages (draw calls) buy a tenth of the
// texels or more. Appends the pages to `atlas`; returns false, `atlas` as it
// was, when no page holds them all.
bool pack_rest(std::vector<Block> left, const std::vector<Eigen::Vector2i>& sizes, int gutter, Atlas& atlas) {
    std::uint64_t face_texels = 0;
    for (const Block& block : left) face_texels += area(block.size);
    // The smallest page holding them all, packed once: the search keeps the packing that fits.
    std::optional<Atlas> alone;
    auto holding = std::find_if(sizes.begin(), sizes.end(), [&](Eigen::Vector2i s) {
        return area(s) >= face_texels && (alone = with_page(atlas, left, s, gutter));
    });
    if (holding == sizes.end()) return false;
    // The squarest page of the largest area below the holding page's (sizes are sorted by area, squarer
    // first).
    auto below = std::find_if(std::make_reverse_iterator(holding), sizes.rend(),
                              [&](Eigen::Vector2i s) { return area(s) < area(*holding); });
    auto smaller =
        below == sizes.rend() ? sizes.end() : std::find_if(sizes.begin(), holding, [&](Eigen::Vector2i s) {
            return area(s) == area(*below);
        });
    if (double(face_texels) < 0.9 * double(area(*holding)) && smaller != sizes.end()) {
        Atlas split = atlas;
        std::vector<Block> rest =
            pack_page(left, *smaller, gutter, int(split.pages.size()), &split.placements);
        split.pages.push_back(*smaller);
        if (rest.size() < left.size() && (rest.empty() || pack_rest(std::move(rest), sizes, gutter, split)) &&
            double(page_texels(split) - page_texels(atlas)) < 0.9 * double(area(*holding))) {
            atlas = std::move(split);
            return true;
        }
    }
    atlas = std::move(*alone);
    return true;
}

// Full pages at the largest size while the rest does not fit one, then the
// rest's page from pack_rest. Whether the rest fits one page is pack_rest's
// search (it tries the largest last), not a packing of the largest page first:
// on `manual`'s levels that packing was half the time of packing.
Atlas pack_blocks(std::vector<Block> left, int min_texture_size, int max_texture_size, int gutter,
                  std::size_t faces) {
    Atlas atlas;
    atlas.placements.resize(faces);
    const std::vector<Eigen::Vector2i> sizes = page_sizes(min_texture_size, max_texture_size);
    while (!left.empty()) {
        if (!cannot_fit(left, sizes.back(), gutter) && pack_rest(left, sizes, gutter, atlas)) break;
        Atlas full = atlas;
        std::vector<Block> rest =
            pack_page(left, sizes.back(), gutter, int(full.pages.size()), &full.placements);
        full.pages.push_back(sizes.back());
        atlas = std::move(full);
        left = std::move(rest);
    }
    return atlas;
}

}  // namespace

Eigen::Vector2i placed_size(const Eigen::Vector2i& face_size, const AtlasPlacement& placement) {
    return placement.rotated ? Eigen::Vector2i(face_size.y(), face_size.x()) : face_size;
}

std::uint64_t page_texels(const Atlas& atlas) {
    std::uint64_t texels = 0;
    for (const Eigen::Vector2i& page : atlas.pages) texels += area(page);
    return texels;
}

std::uint64_t gutter_texels(const Atlas& atlas, const std::vector<Eigen::Vector2i>& face_sizes, int gutter) {
    std::uint64_t texels = 0;
    for (std::size_t i = 0; i < face_sizes.size(); ++i) {
        const AtlasPlacement& at = atlas.placements[i];
        const Eigen::Vector2i block = placed_size(face_sizes[i], at),
                              page = atlas.pages[std::size_t(at.page)];
        const int x0 = std::max(at.x - gutter, 0), x1 = std::min(at.x + block.x() + gutter, page.x());
        const int y0 = std::max(at.y - gutter, 0), y1 = std::min(at.y + block.y() + gutter, page.y());
        texels += std::uint64_t(x1 - x0) * std::uint64_t(y1 - y0) - area(block);
    }
    return texels;
}

Atlas pack_atlas(const std::vector<Eigen::Vector2i>& face_sizes, int min_texture_size, int max_texture_size,
                 int gutter, int threads) {
    for (const Eigen::Vector2i& s : face_sizes)
        if (s.x() > max_texture_size || s.y() > max_texture_size)
            throw std::invalid_argument("pack_atlas: a face is larger than the largest page");
    // Two layouts, keeping the one with fewer page texels (ties: as baked):
    // faces as baked, and every face lying down (wider than tall), which lets
    // the skyline packer stack strips.
    std::vector<Block> as_baked, lying;
    for (std::size_t i = 0; i < face_sizes.size(); ++i) {
        const Eigen::Vector2i s = face_sizes[i];
        as_baked.push_back({int(i), s, false});
        const bool turn = s.y() > s.x();
        lying.push_back({int(i), turn ? Eigen::Vector2i(s.y(), s.x()) : s, turn});
    }
    Atlas layouts[2];
    parallel_for(2, threads, [&](std::size_t k) {
        layouts[k] = pack_blocks(k == 0 ? as_baked : lying, min_texture_size, max_texture_size, gutter,
                                 face_sizes.size());
    });
    return page_texels(layouts[1]) < page_texels(layouts[0]) ? layouts[1] : layouts[0];
}

}  // namespace boxlod
