#include "renderer/texture.h"

#include <algorithm>
#include <cmath>

namespace boxlod {
namespace {

// Box-filtered mip chain; odd sizes clamp the last row/column.
void build_mips(MipTexture& texture) {
    while (texture.levels.back().width > 1 || texture.levels.back().height > 1) {
        const MipTexture::Level& fine = texture.levels.back();
        MipTexture::Level coarse;
        coarse.width = std::max(1, fine.width / 2);
        coarse.height = std::max(1, fine.height / 2);
        coarse.texels.resize(std::size_t(coarse.width) * coarse.height);
        for (int y = 0; y < coarse.height; ++y)
            for (int x = 0; x < coarse.width; ++x) {
                int x0 = std::min(2 * x, fine.width - 1), x1 = std::min(2 * x + 1, fine.width - 1);
                int y0 = std::min(2 * y, fine.height - 1), y1 = std::min(2 * y + 1, fine.height - 1);
                auto at = [&](int i, int j) { return fine.texels[std::size_t(j) * fine.width + i]; };
                coarse.texels[std::size_t(y) * coarse.width + x] = (at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1)) * 0.25f;
            }
        texture.levels.push_back(std::move(coarse));
    }
}

template <typename Convert>
MipTexture texture_from(int width, int height, Wrap wrap, Convert convert) {
    MipTexture texture;
    texture.wrap = wrap;
    MipTexture::Level level;
    level.width = width;
    level.height = height;
    level.texels.resize(std::size_t(width) * height);
    for (std::size_t i = 0; i < level.texels.size(); ++i) level.texels[i] = convert(i);
    texture.levels.push_back(std::move(level));
    build_mips(texture);
    return texture;
}

int wrap_index(int i, int size, Wrap wrap) {
    if (wrap == Wrap::clamp) return std::clamp(i, 0, size - 1);
    i %= size;
    return i < 0 ? i + size : i;
}

Eigen::Vector4f sample_level(const MipTexture::Level& level, Wrap wrap, Eigen::Vector2f uv, bool nearest) {
    float x = uv.x() * float(level.width) - 0.5f, y = uv.y() * float(level.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return level.texels[0];
    // Keep huge repeat coordinates in range before converting to int.
    x = std::clamp(x, -1e7f, 1e7f);
    y = std::clamp(y, -1e7f, 1e7f);
    auto at = [&](int i, int j) {
        return level.texels[std::size_t(wrap_index(j, level.height, wrap)) * level.width + wrap_index(i, level.width, wrap)];
    };
    if (nearest) return at(int(std::floor(x + 0.5f)), int(std::floor(y + 0.5f)));
    float fx = std::floor(x), fy = std::floor(y);
    int i = int(fx), j = int(fy);
    float s = x - fx, t = y - fy;
    return (at(i, j) * (1 - s) + at(i + 1, j) * s) * (1 - t) + (at(i, j + 1) * (1 - s) + at(i + 1, j + 1) * s) * t;
}

}  // namespace

MipTexture make_texture(const Image8& image, ColorSpace space, Wrap wrap) {
    return texture_from(image.width, image.height, wrap, [&](std::size_t i) {
        const std::uint8_t* p = &image.pixels[i * image.channels];
        Eigen::Vector4f v(0, 0, 0, 1);
        for (int c = 0; c < std::min(image.channels, 4); ++c)
            v[c] = (space == ColorSpace::srgb && c < 3) ? srgb_to_linear(p[c]) : float(p[c]) / 255.0f;
        if (image.channels == 1) v.y() = v.z() = v.x();
        return v;
    });
}

MipTexture make_texture(const Image16& image, Wrap wrap) {
    return texture_from(image.width, image.height, wrap, [&](std::size_t i) {
        return Eigen::Vector4f(float(image.pixels[i * image.channels]) / 65535.0f, 0, 0, 1);
    });
}

MipTexture make_texture(const ImageF& image, Wrap wrap) {
    return texture_from(image.width, image.height, wrap,
                        [&](std::size_t i) { return Eigen::Vector4f(image.pixels[i * image.channels], 0, 0, 1); });
}

Eigen::Vector4f sample(const MipTexture& texture, Eigen::Vector2f uv, float lod) {
    if (texture.filter == Filter::nearest) return sample_level(texture.levels[0], texture.wrap, uv, true);
    if (texture.filter == Filter::bilinear || !(lod > 0)) return sample_level(texture.levels[0], texture.wrap, uv, false);
    float top = float(texture.levels.size() - 1);
    lod = std::min(lod, top);
    int fine = int(std::floor(lod));
    float t = lod - float(fine);
    Eigen::Vector4f a = sample_level(texture.levels[fine], texture.wrap, uv, false);
    if (t == 0) return a;
    Eigen::Vector4f b = sample_level(texture.levels[fine + 1], texture.wrap, uv, false);
    return a * (1 - t) + b * t;
}

float mip_level(const MipTexture& texture, const Eigen::Vector2f& duv_dx, const Eigen::Vector2f& duv_dy) {
    float w = float(texture.levels[0].width), h = float(texture.levels[0].height);
    float dx = std::hypot(duv_dx.x() * w, duv_dx.y() * h), dy = std::hypot(duv_dy.x() * w, duv_dy.y() * h);
    float rho = std::max(dx, dy);
    return rho > 1 ? std::log2(rho) : 0;
}

}  // namespace boxlod
