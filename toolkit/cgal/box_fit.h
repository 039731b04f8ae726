// Fitting an oriented box of given axes around points, and keeping boxes
// valid (orthonormal right-handed axes, positive thickness) (docs/design.md: Boxes).
#pragma once
#include "toolkit/model/model.h"

#include <Eigen/Core>
#include <array>
#include <span>

namespace boxlod {

// An orthonormal, right-handed frame close to `axes` (columns): Gram-Schmidt on
// the first two columns, the third is their cross product. Zero or parallel
// columns are replaced by a perpendicular, so the result is always valid.
Eigen::Matrix3d orthonormal_frame(const Eigen::Matrix3d& axes);

// The smallest box with the given axes (columns, orthonormal) that encloses
// every point. The axes are rounded to float first and the half-extents rounded
// up, so the stored float box still encloses the points.
OrientedBox fit_box(const Eigen::Matrix3d& axes, std::span<const Eigen::Vector3f> points);

// The box with every full extent at least `thickness` (flat or point-like input).
OrientedBox with_min_thickness(OrientedBox box, float thickness);

// The eight corners of a box.
std::array<Eigen::Vector3f, 8> box_corners(const OrientedBox& box);

}  // namespace boxlod
