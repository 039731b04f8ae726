// Textures for sampling: linear float RGBA with a mip chain, built once from
// an 8-bit image (sRGB or linear), a 16-bit or a float single-channel image.
#pragma once
#include "renderer/image.h"

#include <Eigen/Core>
#include <vector>

namespace boxlod {

enum class ColorSpace { srgb, linear };
enum class Wrap { repeat, clamp };
enum class Filter { nearest, bilinear, trilinear };

struct MipTexture {
    struct Level {
        int width = 0, height = 0;
        std::vector<Eigen::Vector4f> texels;  // row-major, top row first
    };
    std::vector<Level> levels;  // levels[0] full size; each next one half, down to 1x1
    Wrap wrap = Wrap::repeat;
    Filter filter = Filter::trilinear;
};

MipTexture make_texture(const Image8& image, ColorSpace space, Wrap wrap = Wrap::repeat);
MipTexture make_texture(const Image16& image, Wrap wrap = Wrap::clamp);  // single channel -> R in [0, 1]
MipTexture make_texture(const ImageF& image, Wrap wrap = Wrap::clamp);   // single channel -> R

// uv as in glTF: (0, 0) is the top-left corner of the image, texel centres at
// (i + 0.5) / width. `lod` is the mip level (log2 of texels per pixel).
Eigen::Vector4f sample(const MipTexture& texture, Eigen::Vector2f uv, float lod = 0);

// Mip level for the screen-space derivatives of uv (OpenGL 4.6, 8.14.1).
float mip_level(const MipTexture& texture, const Eigen::Vector2f& duv_dx, const Eigen::Vector2f& duv_dy);

}  // namespace boxlod
