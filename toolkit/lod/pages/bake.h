// Baking a box face (docs/design.md: Baking): an orthographic camera outside the
// face looks along the inward normal; its window is exactly the face and its
// depth range the box's depth. The sub-tree's geometry renders into colour +
// coverage, a tangent-space normal map and a height map, one texel per pixel.
#pragma once
#include "toolkit/drawing/drawable.h"

#include <array>

namespace boxlod {

// A face of an oriented box with its texture frame: tangent along +u (image
// right), bitangent up the image, normal outwards; tangent x bitangent = normal.
struct OrientedBoxFace {
    Eigen::Vector3f center, normal, tangent, bitangent;
    float half_width = 0, half_height = 0;  // along tangent and bitangent
    float half_depth = 0;                   // along the normal: half the box's depth
};

// The six faces in the order +a0, -a0, +a1, -a1, +a2, -a2 of the box's axes.
// The bitangent is the face axis closest to world +Y (for faces looking up or
// down: closest to world -Z), so walls bake upright.
std::array<OrientedBoxFace, 6> oriented_box_faces(const OrientedBox& box);

// A rectangle of texels: its top-left texel (x right, y down) and its size.
struct TexelRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

struct BakedFace {
    Image8 color;       // RGBA, sRGB albedo; alpha = coverage; uncovered colour dilated from covered texels
    Image8 normal;      // RGB, tangent-space normal * 0.5 + 0.5; uncovered (0, 0, 1)
    Image16 height;     // 1 (65535) at the face plane, 0 at the opposite face; uncovered 0
    TexelRect covered;  // the smallest rectangle holding every covered texel; empty when none is
};

BakedFace bake_face(const Drawable& subtree, const OrientedBoxFace& face, const Eigen::Vector2i& texels,
                    int threads);

// Fills every uncovered texel (alpha 0) with the mean colour of its nearest
// covered texels, ring by ring, so filtering never reaches the background.
void dilate_colors(Image8& color);

}  // namespace boxlod
