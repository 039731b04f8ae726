// The manual's viewing aids drawn over a finished frame: the coordinate cross
// and the split-view divider. (Wireframe is part of render(): it needs the
// visibility buffer.)
#pragma once
#include "renderer/camera.h"
#include "renderer/renderer.h"

namespace boxlod {

// X red, Y green, Z blue lines of `length` from `origin`, on top of everything.
void draw_axes(Frame& frame, const Camera& camera, const Eigen::Vector3f& origin, float length);

// A line of world points, clipped at the near plane, `width` pixels wide.
void draw_line(Frame& frame, const Camera& camera, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
               const Eigen::Vector3f& color, int width);

// A vertical line at column x (the split-view divider).
void draw_divider(Frame& frame, int x, const Eigen::Vector3f& color);

}  // namespace boxlod
