// Textures for sampling: a mip chain kept in the image's own 8- or 16-bit
// encoding (as GPUs keep sRGB textures), decoded to linear float per fetch.
// Built once from an 8-bit image (sRGB or linear) or a 16-bit height map.
#pragma once
#include "renderer/image.h"
#include "renderer/lanes.h"

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace boxlod {

enum class ColorSpace { srgb, linear };
enum class Wrap { repeat, clamp };
enum class Filter { nearest, bilinear, trilinear };
enum class TexelFormat {
    srgb8,    // RGBA8, colour sRGB-encoded, alpha linear
    unorm8,   // RGBA8, linear (normal maps)
    unorm16,  // one 16-bit channel (height maps), read as R
    float32,  // one float channel (height maps in world units or [0, 1]), read as R
};

struct MipTexture {
    struct Level {
        int width = 0, height = 0;
        std::vector<std::uint8_t> rgba8;  // srgb8, unorm8: 4 bytes per texel, row-major, top row first
        std::vector<std::uint16_t> r16;   // unorm16
        std::vector<float> r32;           // float32
    };
    TexelFormat format = TexelFormat::unorm8;
    std::vector<Level> levels;  // levels[0] full size; each next one half, down to 1x1
    Wrap wrap = Wrap::repeat;
    Filter filter = Filter::trilinear;
};

MipTexture make_texture(const Image8& image, ColorSpace space, Wrap wrap = Wrap::repeat);  // 1..4 channels
MipTexture make_texture(const Image16& image, Wrap wrap = Wrap::clamp);  // first channel -> R
MipTexture make_texture(const ImageF& image, Wrap wrap = Wrap::clamp);   // first channel -> R

// One texel of one level, decoded to linear (R, G, B, A); unorm16 and float32 give (h, 0, 0, 1).
Eigen::Vector4f texel(const MipTexture& texture, int level, int x, int y);

// uv as in glTF: (0, 0) is the top-left corner of the image, texel centres at
// (i + 0.5) / width. `lod` is the mip level (log2 of texels per pixel).
Eigen::Vector4f sample(const MipTexture& texture, Eigen::Vector2f uv, float lod = 0);
// sample(a, uv, lod_a) and sample(b, uv, lod_b); where both have one size, wrap
// and filter and the lods are equal (a face's colour and normal maps), the
// texels and weights are found once for both.
std::pair<Eigen::Vector4f, Eigen::Vector4f> sample_both(const MipTexture& a, float lod_a, const MipTexture& b,
                                                        float lod_b, Eigen::Vector2f uv);

// Mip level for the screen-space derivatives of uv (OpenGL 4.6, 8.14.1).
float mip_level(const MipTexture& texture, const Eigen::Vector2f& duv_dx, const Eigen::Vector2f& duv_dy);

// The same, in lanes (renderer/lanes.h), with mip_level's bits in each of
// the first `count` lanes.
FloatLanes mip_level(const MipTexture& texture, FloatLanes du_dx, FloatLanes dv_dx, FloatLanes du_dy,
                     FloatLanes dv_dy, int count);
// Whether two textures have one size, wrap and filter: then they read the same texels.
bool same_layout(const MipTexture& a, const MipTexture& b);
// sample_both(a, lod, b, lod, uv) for two textures of one layout, in lanes,
// at the first `count` lanes' uvs and mip levels.
void sample_both(const MipTexture& a, const MipTexture& b, FloatLanes u, FloatLanes v, FloatLanes lod,
                 int count, Vector4Lanes& from_a, Vector4Lanes& from_b);

}  // namespace boxlod
