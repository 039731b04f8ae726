#include "toolkit/lod/pages/level_pages.h"

#include "renderer/image.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

LodPage lod_page(int page) { return {3 * page, 3 * page + 1, 3 * page + 2}; }

void add_pages(Model& out, const Atlas& atlas, float height_depth, bool textured) {
    if (!textured) {
        Material material;
        material.name = "lod_box";
        material.base_color = {0.7f, 0.7f, 0.7f, 1};
        out.materials.push_back(material);
        return;
    }
    for (int page = 0; page < int(atlas.pages.size()); ++page) {
        const Eigen::Vector2i size = atlas.pages[std::size_t(page)];
        Texture color{"color_" + std::to_string(page) + ".png", Image8(size.x(), size.y(), 4, 0), {}};
        Texture normal{"normal_" + std::to_string(page) + ".png", Image8(size.x(), size.y(), 3, 255), {}};
        for (std::size_t i = 0; i < normal.image.pixels.size(); i += 3)
            normal.image.pixels[i] = normal.image.pixels[i + 1] = 128;
        Texture height{"height_" + std::to_string(page) + ".png", {}, Image16(size.x(), size.y(), 1, 0)};
        color.wrap = normal.wrap = height.wrap = Wrap::clamp;  // faces touch the page's border
        const LodPage textures = lod_page(page);
        out.textures.resize(std::size_t(textures.height) + 1);
        out.textures[std::size_t(textures.color)] = std::move(color);
        out.textures[std::size_t(textures.normal)] = std::move(normal);
        out.textures[std::size_t(textures.height)] = std::move(height);
        Material material;
        material.name = "lod_page_" + std::to_string(page);
        material.base_color_texture = textures.color;
        material.normal_texture = textures.normal;
        material.height_texture = textures.height;
        material.height_depth = height_depth;
        material.alpha_mode = AlphaMode::mask;
        // boxlod measures with both sides drawn; through a face's cut-out texels one sees the
        // inside of the box's far faces, so engines must draw both sides too (docs/design.md: Files).
        material.double_sided = true;
        out.materials.push_back(material);
    }
}

int baked_page_material(Model& out, int page, std::map<int, int>& made) {
    auto [at, added] = made.try_emplace(page, int(out.materials.size()));
    if (added) {
        Material material = out.materials[std::size_t(page)];
        material.name += "_proxy";
        material.height_texture = -1;
        material.height_depth = 0;
        material.alpha_mode = AlphaMode::opaque;
        out.materials.push_back(material);
    }
    return at->second;
}

Eigen::Vector2f page_uv(const AtlasPlacement& at, const TexelRect& region, const Eigen::Vector2i& page,
                        float x, float y) {
    const float page_x = at.rotated ? float(region.height) - y : x, page_y = at.rotated ? x : y;
    return {(float(at.x) + page_x) / float(page.x()), (float(at.y) + page_y) / float(page.y())};
}

void place_swatches(const Swatches& swatches, const AtlasPlacement& at, int gutter, Model& out) {
    const LodPage page = lod_page(at.page);
    Texture &color = out.textures[std::size_t(page.color)], &normal = out.textures[std::size_t(page.normal)],
            &height = out.textures[std::size_t(page.height)];
    const Eigen::Vector2i first = swatch_texel(swatches, at, 0);
    const int count = int(swatches.colors.size()), rows = (count + swatches.columns - 1) / swatches.columns;
    const std::uint8_t flat_normal[3] = {128, 128, 255};
    auto swatch_of = [](int texel, int start, int n) {
        return std::clamp(texel < start ? -1 : (texel - start) / swatch_side, 0, n - 1);
    };
    for (int py = std::max(at.y - gutter, 0);
         py < std::min(at.y + swatches.block_side() + gutter, color.image.height); ++py)
        for (int px = std::max(at.x - gutter, 0);
             px < std::min(at.x + swatches.block_side() + gutter, color.image.width); ++px) {
            const int k = std::min(swatch_of(py, first.y(), rows) * swatches.columns +
                                       swatch_of(px, first.x(), swatches.columns),
                                   count - 1);
            std::copy_n(swatches.colors[std::size_t(k)].data(), 4, color.image.at(px, py));
            std::copy_n(flat_normal, 3, normal.image.at(px, py));
            height.image16.at(px, py)[0] = 65535;
        }
}

std::optional<std::array<std::uint8_t, 4>> flat_color(const BakedFace& face, const TexelRect& region,
                                                      int flat_faces) {
    if (std::max(region.width, region.height) > flat_faces) return std::nullopt;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int covered = 0;
    for (int y = region.y; y < region.y + region.height; ++y)
        for (int x = region.x; x < region.x + region.width; ++x) {
            const std::uint8_t* texel = face.color.at(x, y);
            if (texel[3] < 128) continue;  // cut out by the pages' MASK cutoff 0.5
            ++covered;
            for (int c = 0; c < 3; ++c) sum[c] += srgb_to_linear(texel[c]);
        }
    if (2 * covered < region.width * region.height) return std::nullopt;
    std::array<std::uint8_t, 4> color{0, 0, 0, 255};
    for (int c = 0; c < 3; ++c) color[std::size_t(c)] = linear_to_srgb(float(sum[c] / covered));
    return color;
}

Eigen::Vector2i swatch_texel(const Swatches& swatches, const AtlasPlacement& at, int k) {
    auto aligned = [](int v) { return v + (swatch_side - v % swatch_side) % swatch_side; };
    return {aligned(at.x) + swatch_side * (k % swatches.columns),
            aligned(at.y) + swatch_side * (k / swatches.columns)};
}

void place_face(const BakedFace& face, const TexelRect& region, const AtlasPlacement& at, int gutter,
                float depth_ratio, Texture& color, Texture& normal, Texture& height) {
    const Eigen::Vector2i block = placed_size({region.width, region.height}, at);
    const int page_width = color.image.width, page_height = color.image.height;
    for (int by = -gutter; by < block.y() + gutter; ++by)
        for (int bx = -gutter; bx < block.x() + gutter; ++bx) {
            const int px = at.x + bx, py = at.y + by;
            if (px < 0 || py < 0 || px >= page_width || py >= page_height) continue;
            // The region texel at block texel (bx, by); turned clockwise, the region's top row is the block's
            // right column.
            const int rx = at.rotated ? by : bx, ry = at.rotated ? region.height - 1 - bx : by;
            const int sx = std::clamp(region.x + rx, 0, face.color.width - 1),
                      sy = std::clamp(region.y + ry, 0, face.color.height - 1);
            std::copy_n(face.color.at(sx, sy), 4, color.image.at(px, py));
            std::copy_n(face.normal.at(sx, sy), 3, normal.image.at(px, py));
            const float below = float(65535 - face.height.at(sx, sy)[0]) * depth_ratio;
            height.image16.at(px, py)[0] = std::uint16_t(65535 - std::lround(below));
        }
}

}  // namespace boxlod
