#include "renderer/texture.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace boxlod {
namespace {

// Decoding with the format known at compile time: a fetch reads four texels, so
// fetch picks the decoder once per fetch instead of once per texel.
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
    level.width = width;
    level.height = height;
    std::size_t n = std::size_t(width) * height;
    if (format == TexelFormat::unorm16)
        level.r16.resize(n);
    else if (format == TexelFormat::float32)
        level.r32.resize(n);
    else
        level.rgba8.resize(n * 4);
    return level;
}

// Box-filtered mip chain, averaged in linear space; odd sizes clamp the last row/column.
void build_mips(MipTexture& texture) {
    while (texture.levels.back().width > 1 || texture.levels.back().height > 1) {
        const MipTexture::Level& fine = texture.levels.back();
        MipTexture::Level coarse =
            make_level(texture.format, std::max(1, fine.width / 2), std::max(1, fine.height / 2));
        for (int y = 0; y < coarse.height; ++y)
            for (int x = 0; x < coarse.width; ++x) {
                int x0 = std::min(2 * x, fine.width - 1), x1 = std::min(2 * x + 1, fine.width - 1);
                int y0 = std::min(2 * y, fine.height - 1), y1 = std::min(2 * y + 1, fine.height - 1);
                auto at = [&](int i, int j) {
                    return decode(fine, texture.format, std::size_t(j) * fine.width + i);
                };
                encode(coarse, texture.format, std::size_t(y) * coarse.width + x,
                       (at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1)) * 0.25f);
            }
        texture.levels.push_back(std::move(coarse));
    }
}

int wrap_index(int i, int size, Wrap wrap) {
    if (wrap == Wrap::clamp) return std::clamp(i, 0, size - 1);
    // A power-of-two size (nearly every texture) wraps by a mask: the same
    // index for negative i too (two's complement), without a division.
    if ((size & (size - 1)) == 0) return i & (size - 1);
    i %= size;
    return i < 0 ? i + size : i;
}

// wrap_index(next, size, wrap) for next = i + 1, given wrapped = wrap_index(i, size, wrap).
int wrap_next(int wrapped, int next, int size, Wrap wrap) {
    if (wrap == Wrap::clamp) return std::clamp(next, 0, size - 1);
    return wrapped + 1 == size ? 0 : wrapped + 1;
}

// Where one fetch from one level reads: a bilinear fetch four texels and
// their weights, a nearest one (or one at a non-finite coordinate) a single texel.
struct Footprint {
    std::size_t k00 = 0, k10 = 0, k01 = 0, k11 = 0;
    float s = 0, t = 0;
    bool single = true;
};

Footprint footprint(const MipTexture::Level& level, Wrap wrap, Eigen::Vector2f uv, bool nearest) {
    Footprint f;
    float x = uv.x() * float(level.width) - 0.5f, y = uv.y() * float(level.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return f;
    // Keep huge repeat coordinates in range before converting to int.
    x = std::clamp(x, -1e7f, 1e7f);
    y = std::clamp(y, -1e7f, 1e7f);
    if (nearest) {
        f.k00 = std::size_t(wrap_index(int(std::floor(y + 0.5f)), level.height, wrap)) * level.width +
                wrap_index(int(std::floor(x + 0.5f)), level.width, wrap);
        return f;
    }
    float fx = std::floor(x), fy = std::floor(y);
    int i = int(fx), j = int(fy);
    f.single = false;
    f.s = x - fx;
    f.t = y - fy;
    if (i >= 0 && j >= 0 && i + 1 < level.width &&
        j + 1 < level.height) {  // inside: no wrapping (most samples)
        f.k00 = std::size_t(j) * level.width + i;
        f.k10 = f.k00 + 1;
        f.k01 = f.k00 + std::size_t(level.width);
        f.k11 = f.k01 + 1;
    } else {  // each coordinate wrapped once, its neighbour from it (a tiled texture's every sample lands
              // here)
        const int i0 = wrap_index(i, level.width, wrap), j0 = wrap_index(j, level.height, wrap);
        const int i1 = wrap_next(i0, i + 1, level.width, wrap), j1 = wrap_next(j0, j + 1, level.height, wrap);
        const std::size_t row0 = std::size_t(j0) * level.width, row1 = std::size_t(j1) * level.width;
        f.k00 = row0 + i0;
        f.k10 = row0 + i1;
        f.k01 = row1 + i0;
        f.k11 = row1 + i1;
    }
    return f;
}

template <TexelFormat format>
Eigen::Vector4f fetch_as(const MipTexture::Level& level, const Footprint& f) {
    auto at = [&](std::size_t k) { return decode_as<format>(level, k); };
    if (f.single) return at(f.k00);
    const float s = f.s, t = f.t;
    return (at(f.k00) * (1 - s) + at(f.k10) * s) * (1 - t) + (at(f.k01) * (1 - s) + at(f.k11) * s) * t;
}

Eigen::Vector4f fetch(const MipTexture& texture, int index, const Footprint& f) {
    const MipTexture::Level& level = texture.levels[std::size_t(index)];
    switch (texture.format) {
    case TexelFormat::srgb8: return fetch_as<TexelFormat::srgb8>(level, f);
    case TexelFormat::unorm8: return fetch_as<TexelFormat::unorm8>(level, f);
    case TexelFormat::unorm16: return fetch_as<TexelFormat::unorm16>(level, f);
    case TexelFormat::float32: break;
    }
    return fetch_as<TexelFormat::float32>(level, f);
}

// What a sample reads: one level, or two blended by `blend` (trilinear,
// OpenGL 4.6 8.14.2), each with its footprint.
struct SamplePlan {
    int level[2] = {0, 0};
    int count = 1;
    float blend = 0;
    Footprint at[2];
};

// Sets the levels a sample at `lod` reads and their blend into a plan as
// constructed (level 0 alone); not its footprints.
[[gnu::always_inline]] inline void plan_levels(const MipTexture& texture, float lod, SamplePlan& plan) {
    if (texture.filter != Filter::trilinear || !(lod > 0)) return;
    lod = std::min(lod, float(texture.levels.size() - 1));
    const int fine = int(std::floor(lod));
    plan.level[0] = fine;
    plan.blend = lod - float(fine);
    if (plan.blend != 0) {
        plan.count = 2;
        plan.level[1] = fine + 1;
    }
}

SamplePlan plan_sample(const MipTexture& texture, Eigen::Vector2f uv, float lod) {
    SamplePlan plan;
    if (texture.filter == Filter::nearest) {
        plan.at[0] = footprint(texture.levels[0], texture.wrap, uv, true);
        return plan;
    }
    plan_levels(texture, lod, plan);
    plan.at[0] = footprint(texture.levels[std::size_t(plan.level[0])], texture.wrap, uv, false);
    if (plan.count == 2)
        plan.at[1] = footprint(texture.levels[std::size_t(plan.level[1])], texture.wrap, uv, false);
    return plan;
}

// std::floor for |x| < 2^31 (footprint clamps to 1e7), in SSE2: the truncation, less one where it rounded up.
FloatLanes floor_lanes(FloatLanes x) {
    const FloatLanes truncated = _mm_cvtepi32_ps(_mm_cvttps_epi32(x));
    return truncated - select(truncated > x, broadcast(1.0f), broadcast(0.0f));
}

// plan_sample at the first `count` lanes, its footprints' arithmetic four lanes
// at a time (the same operations, so the same floats and texels): the
// coordinates, their floors, weights and wrapped texels. Lanes at non-finite
// coordinates or repeating a level whose size is not a power of two go
// through footprint().
void plan_samples(const MipTexture& texture, FloatLanes u, FloatLanes v, FloatLanes lod, int count,
                  SamplePlan* plans) {
    if (texture.filter != Filter::trilinear) {
        for (int j = 0; j < count; ++j) plans[j] = plan_sample(texture, {u[j], v[j]}, lod[j]);
        return;
    }
    for (int j = 0; j < count; ++j) plan_levels(texture, lod[j], plans[j]);
    for (int slot = 0; slot < 2; ++slot) {
        IntLanes width{}, height{};
        for (int j = 0; j < count; ++j) {
            const MipTexture::Level& level = texture.levels[std::size_t(plans[j].level[slot])];
            width[j] = level.width;
            height[j] = level.height;
        }
        FloatLanes x = u * __builtin_convertvector(width, FloatLanes) - 0.5f;
        FloatLanes y = v * __builtin_convertvector(height, FloatLanes) - 0.5f;
        const IntLanes finite = (x - x == 0) & (y - y == 0);               // inf - inf and NaN - NaN are NaN
        x = _mm_min_ps(_mm_max_ps(x, broadcast(-1e7f)), broadcast(1e7f));  // std::clamp for finite x
        y = _mm_min_ps(_mm_max_ps(y, broadcast(-1e7f)), broadcast(1e7f));
        const FloatLanes fx = floor_lanes(x), fy = floor_lanes(y);
        const IntLanes i = IntLanes(_mm_cvttps_epi32(fx)), jy = IntLanes(_mm_cvttps_epi32(fy));
        const FloatLanes s = x - fx, t = y - fy;
        // wrap_index and wrap_next in lanes; repeat where the level's size is a power of two.
        const IntLanes last_x = width - 1, last_y = height - 1, zero{};
        IntLanes i0, i1, j0, j1, in_lanes = finite;
        auto clamp = [&](IntLanes value, IntLanes last) {
            return value < 0 ? zero : (last < value ? last : value);
        };
        if (texture.wrap == Wrap::clamp) {
            i0 = clamp(i, last_x);
            i1 = clamp(i + 1, last_x);
            j0 = clamp(jy, last_y);
            j1 = clamp(jy + 1, last_y);
        } else {
            in_lanes &= ((width & last_x) == 0) & ((height & last_y) == 0);
            i0 = i & last_x;
            j0 = jy & last_y;
            i1 = i0 + 1 == width ? zero : i0 + 1;
            j1 = j0 + 1 == height ? zero : j0 + 1;
        }
        for (int j = 0; j < count; ++j) {
            SamplePlan& plan = plans[j];
            if (slot == 1 && plan.count == 1) continue;
            Footprint& f = plan.at[slot];
            if (!in_lanes[j]) {
                f = footprint(texture.levels[std::size_t(plan.level[slot])], texture.wrap, {u[j], v[j]},
                              false);
                continue;
            }
            f.single = false;
            f.s = s[j];
            f.t = t[j];
            const std::size_t row0 = std::size_t(j0[j]) * std::size_t(width[j]),
                              row1 = std::size_t(j1[j]) * std::size_t(width[j]);
            f.k00 = row0 + std::size_t(i0[j]);
            f.k10 = row0 + std::size_t(i1[j]);
            f.k01 = row1 + std::size_t(i0[j]);
            f.k11 = row1 + std::size_t(i1[j]);
        }
    }
}

Eigen::Vector4f sample_planned(const MipTexture& texture, const SamplePlan& plan) {
    Eigen::Vector4f a = fetch(texture, plan.level[0], plan.at[0]);
    if (plan.count == 1) return a;
    Eigen::Vector4f b = fetch(texture, plan.level[1], plan.at[1]);
    return a * (1 - plan.blend) + b * plan.blend;
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
        if (image.channels <= 2) {
            q[0] = q[1] = q[2] = p[0];
            q[3] = image.channels == 2 ? p[1] : 255;
        } else {
            q[0] = p[0];
            q[1] = p[1];
            q[2] = p[2];
            q[3] = image.channels == 4 ? p[3] : 255;
        }
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
    return sample_planned(texture, plan_sample(texture, uv, lod));
}

std::pair<Eigen::Vector4f, Eigen::Vector4f> sample_both(const MipTexture& a, float lod_a, const MipTexture& b,
                                                        float lod_b, Eigen::Vector2f uv) {
    const SamplePlan plan = plan_sample(a, uv, lod_a);
    if (lod_a == lod_b && same_layout(a, b)) return {sample_planned(a, plan), sample_planned(b, plan)};
    return {sample_planned(a, plan), sample(b, uv, lod_b)};
}

// Two textures read the same texels where they share size, wrap and filter.
bool same_layout(const MipTexture& a, const MipTexture& b) {
    return a.wrap == b.wrap && a.filter == b.filter && a.levels.size() == b.levels.size() &&
           a.levels[0].width == b.levels[0].width && a.levels[0].height == b.levels[0].height;
}

void sample_both(const MipTexture& a, const MipTexture& b, FloatLanes u, FloatLanes v, FloatLanes lod,
                 int count, Vector4Lanes& from_a, Vector4Lanes& from_b) {
    SamplePlan plans[lane_count];
    plan_samples(a, u, v, lod, count, plans);
    for (int j = 0; j < count; ++j) {
        const SamplePlan& plan = plans[j];
        const Eigen::Vector4f texel_a = sample_planned(a, plan), texel_b = sample_planned(b, plan);
        from_a.x[j] = texel_a.x();
        from_a.y[j] = texel_a.y();
        from_a.z[j] = texel_a.z();
        from_a.w[j] = texel_a.w();
        from_b.x[j] = texel_b.x();
        from_b.y[j] = texel_b.y();
        from_b.z[j] = texel_b.z();
        from_b.w[j] = texel_b.w();
    }
}

// glibc's hypotf rounds the exact double sum of squares' square root to float
// (checked against it on 2e8 finite pairs, bit patterns and small values);
// a non-finite lane takes hypotf itself.
FloatLanes mip_level(const MipTexture& texture, FloatLanes du_dx, FloatLanes dv_dx, FloatLanes du_dy,
                     FloatLanes dv_dy, int count) {
    const FloatLanes w = broadcast(float(texture.levels[0].width)),
                     h = broadcast(float(texture.levels[0].height));
    auto hypot = [&](FloatLanes a, FloatLanes b) {
        const DoubleLanes da = to_doubles(a), db = to_doubles(b);
        FloatLanes length = to_floats(square_root(da * da + db * db));
        for (int j = 0; j < count; ++j)
            if (!std::isfinite(a[j]) || !std::isfinite(b[j])) length[j] = std::hypot(a[j], b[j]);
        return length;
    };
    const FloatLanes dx = hypot(du_dx * w, dv_dx * h), dy = hypot(du_dy * w, dv_dy * h);
    const FloatLanes rho = select(dx < dy, dy, dx);  // std::max(dx, dy)
    FloatLanes lod{};
    for (int j = 0; j < count; ++j)
        if (rho[j] > 1) lod[j] = std::log2(rho[j]);
    return lod;
}

float mip_level(const MipTexture& texture, const Eigen::Vector2f& duv_dx, const Eigen::Vector2f& duv_dy) {
    float w = float(texture.levels[0].width), h = float(texture.levels[0].height);
    float dx = std::hypot(duv_dx.x() * w, duv_dx.y() * h), dy = std::hypot(duv_dy.x() * w, duv_dy.y() * h);
    float rho = std::max(dx, dy);
    return rho > 1 ? std::log2(rho) : 0;
}

}  // namespace boxlod
