// CGAL's optimal (minimum-volume) oriented bounding box (docs/design.md: Boxes).
// The only file that sees CGAL; it is built as its own library (boxlod_obb)
// because CGAL forces -frounding-math on whatever links it.
#pragma once
#include "toolkit/model/model.h"

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

namespace boxlod {

// The extreme points (vertices of the convex hull) of `points`, sorted
// lexicographically, without duplicates or negative zeros. The minimal box
// depends on these only, and the hull vertices of a union are the hull
// vertices of the union of the parts' hull vertices, so sub-trees can be
// reduced bottom-up without changing any box.
std::vector<Eigen::Vector3f> hull_vertices(std::span<const Eigen::Vector3f> points);

// What the minimal box's orientation depends on: the hull vertices relative to
// the first one (exact in double) and whether they are flat up to float
// rounding. Translated copies (windows of a facade) have equal shapes.
struct HullShape {
    std::vector<Eigen::Vector3d> relative;
    bool flat = false;
    bool operator==(const HullShape&) const = default;
};
HullShape hull_shape(std::span<const Eigen::Vector3f> hull);

// The minimal box's axes for a hull shape: CGAL, or the flat/collinear/point
// cases solved directly. Equal shapes and seeds give bit-identical axes.
Eigen::Matrix3d minimal_box_axes(const HullShape& shape, std::uint64_t seed);

// The box with those axes around the hull vertices, with the thickness floor below.
OrientedBox fit_minimal_box(const Eigen::Matrix3d& axes, std::span<const Eigen::Vector3f> hull);

// The minimum-volume box of `points` (CGAL::oriented_bounding_box with
// `seed`); the same point set (in any order) and seed give a bit-identical box.
// Degenerate sets (a point, collinear, coplanar) are solved without CGAL and
// get a small positive thickness (1e-4 of their size, at least 1e-6). Axes are
// orthonormal and right-handed. An empty set gives a tiny box at the origin.
// Equals fit_minimal_box(minimal_box_axes(hull_shape(hull), seed), hull) with
// hull = hull_vertices(points).
OrientedBox minimal_box(std::span<const Eigen::Vector3f> points, std::uint64_t seed);

}  // namespace boxlod
