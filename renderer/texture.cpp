#include "renderer/texture.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace boxlod {
namespace {

// Decoding with the format known at compile time: a fetch reads four texels or eight, so
// sample_level picks the decoder once per fetch instead of once per texel.
// v / 255 for every 8-bit v: the same floats as dividing, without a division per channel.
const std::array<float, 256> unorm8_table = [] {
    std::array<float, 256> table{};
    for (int v = 0; v < 256; ++v) table[std::size_t(v)] = float(v) / 255.0f;
    return table;
}();

template <TexelFormat format>
Eigen::Vector4f decode_as(const MipTexture::Level& level, std::size_t i) {
    if constexpr (format == TexelFormat::unorm16) return {float(level.r16[i]) / 65535.0f, 0, 0, 1};
    if constexpr (format == TexelFormat::float32) return {level.r32[i], 0, 0, 1};
    const std::uint8_t* p = &level.rgba8[i * 4];
    if constexpr (format == TexelFormat::srgb8)
        return {srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]), unorm8_table[p[3]]};
    return {unorm8_table[p[0]], unorm8_table[p[1]], unorm8_table[p[2]], unorm8_table[p[3]]};
}

Eigen::Vector4f decode(const MipTexture::Level& level, TexelFormat format, std::size_t i) {
    switch (format) {
        case TexelFormat::srgb8: return decode_as<TexelFormat::srgb8>(level, i);
        case TexelFormat::unorm8: return decode_as<TexelFormat::unorm8>(level, i);
        case TexelFormat::unorm16: return decode_as<TexelFormat::unorm16>(level, i);
        case TexelFormat::float32: break;
    }
    return decode_as<TexelFormat::float32>(level, i);
}

std::uint8_t unorm8(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); }

void encode(MipTexture::Level& level, TexelFormat format, std::size_t i, const Eigen::Vector4f& v) {
    if (format == TexelFormat::unorm16) {
        level.r16[i] = std::uint16_t(std::lround(std::clamp(v.x(), 0.0f, 1.0f) * 65535));
        return;
    }
    if (format == TexelFormat::float32) {
        level.r32[i] = v.x();
        return;
    }
    std::uint8_t* p = &level.rgba8[i * 4];
    for (int c = 0; c < 3; ++c) p[c] = format == TexelFormat::srgb8 ? linear_to_srgb(v[c]) : unorm8(v[c]);
    p[3] = unorm8(v.w());
}

MipTexture::Level make_level(TexelFormat format, int width, int height) {
    MipTexture::Level level;
    level.width = width, level.height = height;
    std::size_t n = std::size_t(width) * height;
    if (format == TexelFormat::unorm16) level.r16.resize(n);
    else if (format == TexelFormat::float32) level.r32.resize(n);
    else level.rgba8.resize(n * 4);
    return level;
}

// Box-filtered mip chain, averaged in linear space; odd sizes clamp the last row/column.
void build_mips(MipTexture& texture) {
    while (texture.levels.back().width > 1 || texture.levels.back().height > 1) {
        const MipTexture::Level& fine = texture.levels.back();
        MipTexture::Level coarse = make_level(texture.format, std::max(1, fine.width / 2), std::max(1, fine.height / 2));
        for (int y = 0; y < coarse.height; ++y)
            for (int x = 0; x < coarse.width; ++x) {
                int x0 = std::min(2 * x, fine.width - 1), x1 = std::min(2 * x + 1, fine.width - 1);
                int y0 = std::min(2 * y, fine.height - 1), y1 = std::min(2 * y + 1, fine.height - 1);
                auto at = [&](int i, int j) { return decode(fine, texture.format, std::size_t(j) * fine.width + i); };
                encode(coarse, texture.format, std::size_t(y) * coarse.width + x,
                       (at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1)) * 0.25f);
            }
        texture.levels.push_back(std::move(coarse));
    }
}

int wrap_index(int i, int size, Wrap wrap) {
    if (wrap == Wrap::clamp) return std::clamp(i, 0, size - 1);
    i %= size;
    return i < 0 ? i + size : i;
}

// wrap_index(next, size, wrap) for next = i + 1, given wrapped = wrap_index(i, size, wrap).
int wrap_next(int wrapped, int next, int size, Wrap wrap) {
    if (wrap == Wrap::clamp) return std::clamp(next, 0, size - 1);
    return wrapped + 1 == size ? 0 : wrapped + 1;
}

template <TexelFormat format>
Eigen::Vector4f sample_level_as(const MipTexture& texture, int index, Eigen::Vector2f uv, bool nearest) {
    const MipTexture::Level& level = texture.levels[index];
    float x = uv.x() * float(level.width) - 0.5f, y = uv.y() * float(level.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return decode_as<format>(level, 0);
    // Keep huge repeat coordinates in range before converting to int.
    x = std::clamp(x, -1e7f, 1e7f);
    y = std::clamp(y, -1e7f, 1e7f);
    auto wrapped = [&](int i, int j) {
        return std::size_t(wrap_index(j, level.height, texture.wrap)) * level.width + wrap_index(i, level.width, texture.wrap);
    };
    if (nearest) return decode_as<format>(level, wrapped(int(std::floor(x + 0.5f)), int(std::floor(y + 0.5f))));
    float fx = std::floor(x), fy = std::floor(y);
    int i = int(fx), j = int(fy);
    float s = x - fx, t = y - fy;
    std::size_t k00, k10, k01, k11;
    if (i >= 0 && j >= 0 && i + 1 < level.width && j + 1 < level.height) {  // inside: no wrapping (most samples)
        k00 = std::size_t(j) * level.width + i, k10 = k00 + 1, k01 = k00 + std::size_t(level.width), k11 = k01 + 1;
    } else {  // each coordinate wrapped once, its neighbour from it (a tiled texture's every sample lands here)
        const int i0 = wrap_index(i, level.width, texture.wrap), j0 = wrap_index(j, level.height, texture.wrap);
        const int i1 = wrap_next(i0, i + 1, level.width, texture.wrap), j1 = wrap_next(j0, j + 1, level.height, texture.wrap);
        const std::size_t row0 = std::size_t(j0) * level.width, row1 = std::size_t(j1) * level.width;
        k00 = row0 + i0, k10 = row0 + i1, k01 = row1 + i0, k11 = row1 + i1;
    }
    auto at = [&](std::size_t k) { return decode_as<format>(level, k); };
    return (at(k00) * (1 - s) + at(k10) * s) * (1 - t) + (at(k01) * (1 - s) + at(k11) * s) * t;
}

Eigen::Vector4f sample_level(const MipTexture& texture, int index, Eigen::Vector2f uv, bool nearest) {
    switch (texture.format) {
        case TexelFormat::srgb8: return sample_level_as<TexelFormat::srgb8>(texture, index, uv, nearest);
        case TexelFormat::unorm8: return sample_level_as<TexelFormat::unorm8>(texture, index, uv, nearest);
        case TexelFormat::unorm16: return sample_level_as<TexelFormat::unorm16>(texture, index, uv, nearest);
        case TexelFormat::float32: break;
    }
    return sample_level_as<TexelFormat::float32>(texture, index, uv, nearest);
}

// Height maps: the first channel of the image, stored as it is.
template <typename T>
MipTexture single_channel_texture(const Image<T>& image, TexelFormat format, Wrap wrap,
                                  std::vector<T> MipTexture::Level::*store) {
    MipTexture texture;
    texture.format = format;
    texture.wrap = wrap;
    MipTexture::Level level = make_level(format, image.width, image.height);
    std::vector<T>& texels = level.*store;
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = image.pixels[i * image.channels];
    texture.levels.push_back(std::move(level));
    build_mips(texture);
    return texture;
}

}  // namespace

MipTexture make_texture(const Image8& image, ColorSpace space, Wrap wrap) {
    MipTexture texture;
    texture.format = space == ColorSpace::srgb ? TexelFormat::srgb8 : TexelFormat::unorm8;
    texture.wrap = wrap;
    MipTexture::Level level = make_level(texture.format, image.width, image.height);
    for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
        const std::uint8_t* p = &image.pixels[i * image.channels];
        std::uint8_t* q = &level.rgba8[i * 4];
        if (image.channels <= 2) q[0] = q[1] = q[2] = p[0], q[3] = image.channels == 2 ? p[1] : 255;
        else q[0] = p[0], q[1] = p[1], q[2] = p[2], q[3] = image.channels == 4 ? p[3] : 255;
    }
    texture.levels.push_back(std::move(level));
    build_mips(texture);
    return texture;
}

MipTexture make_texture(const Image16& image, Wrap wrap) {
    return single_channel_texture(image, TexelFormat::unorm16, wrap, &MipTexture::Level::r16);
}

MipTexture make_texture(const ImageF& image, Wrap wrap) {
    return single_channel_texture(image, TexelFormat::float32, wrap, &MipTexture::Level::r32);
}



Eigen::Vector4f texel(const MipTexture& texture, int level, int x, int y) {
    const MipTexture::Level& l = texture.levels[level];
    return decode(l, texture.format, std::size_t(y) * l.width + x);
}

Eigen::Vector4f sample(const MipTexture& texture, Eigen::Vector2f uv, float lod) {
    if (texture.filter == Filter::nearest) return sample_level(texture, 0, uv, true);
    if (texture.filter == Filter::bilinear || !(lod > 0)) return sample_level(texture, 0, uv, false);
    float top = float(texture.levels.size() - 1);
    lod = std::min(lod, top);
    int fine = int(std::floor(lod));
    float t = lod - float(fine);
    Eigen::Vector4f a = sample_level(texture, fine, uv, false);
    if (t == 0) return a;
    Eigen::Vector4f b = sample_level(texture, fine + 1, uv, false);
    return a * (1 - t) + b * t;
}

float mip_level(const MipTexture& texture, const Eigen::Vector2f& duv_dx, const Eigen::Vector2f& duv_dy) {
    float w = float(texture.levels[0].width), h = float(texture.levels[0].height);
    float dx = std::hypot(duv_dx.x() * w, duv_dx.y() * h), dy = std::hypot(duv_dy.x() * w, duv_dy.y() * h);
    float rho = std::max(dx, dy);
    return rho > 1 ? std::log2(rho) : 0;
}

}  // namespace boxlod
