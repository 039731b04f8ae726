// Texel = pixel (docs/design.md: Texture sizing; the manual's Textures section):
// a virtual camera with vertical field of view fovy at distance d on a screen
// `resolution` pixels high sees one pixel as p = 2 d tan(fovy / 2) / resolution
// world units; a face a x b gets ceil(a / p) x ceil(b / p) texels.
#pragma once
#include <Eigen/Core>

namespace boxlod {

struct TextureSizing {
    float fovy_degrees = 45;
    float distance = 100;
    float resolution = 1080;
    int max_texture_size = 4096;
    int gutter = 2;  // texels kept free around each face in the atlas, per side
};

double pixel_world_size(const TextureSizing& sizing);  // p
// The sizing whose texels are `factor` times as large: its distance times factor.
TextureSizing coarser_sizing(const TextureSizing& sizing, double factor);
// tan(fovy / 2): the last angle's is kept per thread, as run-time selection
// asks for it per level of every object each frame (docs/city.md: Selection speed).
double half_fovy_tangent(float fovy_degrees);

// Texels for a face of extents a x b: at least 1, at most max_texture_size -
// 2 gutter on each side, scaled down uniformly when larger.
Eigen::Vector2i face_texels(float a, float b, const TextureSizing& sizing);

// The smallest distance at which a face whose longer side is `longest_side`
// still maps 1:1 into max_texture_size (the manual's Min. Distance).
float min_distance(float longest_side, const TextureSizing& sizing);

}  // namespace boxlod
