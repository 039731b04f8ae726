#include "toolkit/cgal/minimal_box.h"

#include "toolkit/cgal/box_fit.h"

#include <Eigen/Dense>  // cross products, determinants

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/optimal_bounding_box.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

namespace boxlod {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// float -> double is exact, so CGAL's exact predicates see the stored coordinates.
std::vector<Point> to_points(std::span<const Eigen::Vector3f> points) {
    std::vector<Point> out;
    out.reserve(points.size());
    for (const Eigen::Vector3f& p : points) out.emplace_back(p.x(), p.y(), p.z());
    return out;
}

std::vector<Point> to_points(const std::vector<Eigen::Vector3d>& points) {
    std::vector<Point> out;
    out.reserve(points.size());
    for (const Eigen::Vector3d& p : points) out.emplace_back(p.x(), p.y(), p.z());
    return out;
}

bool lexicographic_less(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

enum class Shape { point, line, plane, solid };

// The dimension of a set of distinct points, decided with exact predicates.
Shape classify(const std::vector<Point>& points) {
    if (points.size() < 2) return Shape::point;
    const Point& a = points[0];
    const Point& b = points[1];
    auto c =
        std::find_if(points.begin(), points.end(), [&](const Point& p) { return !CGAL::collinear(a, b, p); });
    if (c == points.end()) return Shape::line;
    auto d = std::find_if(points.begin(), points.end(),
                          [&](const Point& p) { return !CGAL::coplanar(a, b, *c, p); });
    return d == points.end() ? Shape::plane : Shape::solid;
}

// A right-handed frame whose first axis is `axis` (the other two completed by orthonormal_frame).
Eigen::Matrix3d frame_with_first_axis(const Eigen::Vector3d& axis) {
    Eigen::Matrix3d columns = Eigen::Matrix3d::Zero();
    columns.col(0) = axis;
    return orthonormal_frame(columns);
}

Eigen::Matrix3d line_frame(const std::vector<Eigen::Vector3d>& relative) {
    return frame_with_first_axis(relative.back() - relative.front());
}

// The normal of the plane through a well-conditioned triple of the points
// (relative to the first): the first, the farthest from it, the farthest from their line.
Eigen::Vector3d plane_normal(const std::vector<Eigen::Vector3d>& relative) {
    Eigen::Vector3d p1 = Eigen::Vector3d::Zero(), p2 = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : relative)
        if (p.norm() > p1.norm()) p1 = p;
    const Eigen::Vector3d line = p1.normalized();
    for (const Eigen::Vector3d& p : relative)
        if (line.cross(p).norm() > line.cross(p2).norm()) p2 = p;
    return line.cross(p2).normalized();
}

// Points that are coplanar but for float rounding (a quad moved by a float
// transform) would leave CGAL's volume search without a gradient in the plane,
// so they are solved as flat. Tolerance: a few float ulps of the coordinates,
// or 1e-6 of the set's size.
bool nearly_flat(std::span<const Eigen::Vector3f> hull) {
    if (hull.size() < 4) return true;
    std::vector<Eigen::Vector3d> relative;
    for (const Eigen::Vector3f& p : hull) relative.push_back(p.cast<double>() - hull[0].cast<double>());
    const Eigen::Vector3d normal = plane_normal(relative);
    double size = 0, magnitude = 0, distance = 0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        size = std::max(size, relative[i].norm());
        magnitude = std::max(magnitude, double(hull[i].cwiseAbs().maxCoeff()));
        distance = std::max(distance, std::abs(normal.dot(relative[i])));
    }
    return distance <= std::max(1e-6 * size, 8 * double(std::numeric_limits<float>::epsilon()) * magnitude);
}

// Andrew's monotone chain (Andrew 1979): the convex polygon of 2D points, counter-clockwise.
std::vector<Eigen::Vector2d> convex_polygon(std::vector<Eigen::Vector2d> q) {
    auto less = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    };
    std::sort(q.begin(), q.end(), less);
    q.erase(std::unique(q.begin(), q.end()), q.end());
    if (q.size() < 3) return q;
    auto turn = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::vector<Eigen::Vector2d> hull(2 * q.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], q[i]) <= 0) --k;
        hull[k++] = q[i];
    }
    for (std::size_t i = q.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], q[i]) <= 0) --k;
        hull[k++] = q[i];
    }
    hull.resize(k - 1);
    return hull;
}

// Flat points: the minimum-area enclosing rectangle has a side collinear with
// an edge of the convex polygon (Freeman & Shapira 1975), so every edge
// direction of the polygon is tried; the plane's normal is the third axis.
Eigen::Matrix3d plane_frame(const std::vector<Eigen::Vector3d>& relative) {
    const Eigen::Matrix3d plane = frame_with_first_axis(plane_normal(relative));
    const Eigen::Vector3d n = plane.col(0), u = plane.col(1), v = plane.col(2);
    std::vector<Eigen::Vector2d> q;
    for (const Eigen::Vector3d& p : relative) q.emplace_back(u.dot(p), v.dot(p));
    const std::vector<Eigen::Vector2d> polygon = convex_polygon(q);

    double best_area = std::numeric_limits<double>::infinity();
    Eigen::Vector2d best = Eigen::Vector2d::UnitX();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector2d edge = polygon[(i + 1) % polygon.size()] - polygon[i];
        if (edge.norm() == 0) continue;
        const Eigen::Vector2d d = edge.normalized(), e(-d.y(), d.x());
        double lo_d = std::numeric_limits<double>::infinity(), hi_d = -lo_d, lo_e = lo_d, hi_e = -lo_d;
        for (const Eigen::Vector2d& p : polygon) {
            lo_d = std::min(lo_d, p.dot(d));
            hi_d = std::max(hi_d, p.dot(d));
            lo_e = std::min(lo_e, p.dot(e));
            hi_e = std::max(hi_e, p.dot(e));
        }
        const double area = (hi_d - lo_d) * (hi_e - lo_e);
        if (area < best_area) {
            best_area = area;
            best = d;
        }
    }
    const Eigen::Vector3d axis = best.x() * u + best.y() * v;
    Eigen::Matrix3d frame;
    frame << axis, n.cross(axis), n;
    return orthonormal_frame(frame);
}

// The general case: CGAL's optimizer (Chang, Gorissen & Melchior 2011, as
// implemented in CGAL) returns the rotation that maps the box to an axis-aligned
// one; its rows are the box axes.
Eigen::Matrix3d solid_frame(const std::vector<Point>& points, std::uint64_t seed) {
    Kernel::Aff_transformation_3 rotation;
    const auto seed32 = static_cast<unsigned int>(seed ^ (seed >> 32));
    CGAL::oriented_bounding_box(points, rotation,
                                CGAL::parameters::use_convex_hull(true).random_seed(seed32));
    Eigen::Matrix3d rows;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) rows(r, c) = CGAL::to_double(rotation.m(r, c));
    return orthonormal_frame(rows.transpose());
}

}  // namespace

std::vector<Eigen::Vector3f> hull_vertices(std::span<const Eigen::Vector3f> points) {
    if (points.empty()) return {};
    std::vector<Point> extreme;
    CGAL::extreme_points_3(to_points(points), std::back_inserter(extreme));
    std::vector<Eigen::Vector3f> out;
    out.reserve(extreme.size());
    for (const Point& p : extreme) {
        // Exact: every extreme point is one of the float inputs. Adding +0 turns -0 into +0.
        Eigen::Vector3f v(float(p.x()), float(p.y()), float(p.z()));
        out.push_back(v + Eigen::Vector3f::Zero());
    }
    std::sort(out.begin(), out.end(), lexicographic_less);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

HullShape hull_shape(std::span<const Eigen::Vector3f> hull) {
    HullShape shape;
    for (const Eigen::Vector3f& p : hull) shape.relative.push_back(p.cast<double>() - hull[0].cast<double>());
    shape.flat = nearly_flat(hull);
    return shape;
}

Eigen::Matrix3d minimal_box_axes(const HullShape& shape, std::uint64_t seed) {
    if (shape.relative.empty()) return Eigen::Matrix3d::Identity();
    // The differences are exact, so the exact predicates classify as on the original points.
    const std::vector<Point> points = to_points(shape.relative);
    switch (classify(points)) {
    case Shape::point: return Eigen::Matrix3d::Identity();
    case Shape::line: return line_frame(shape.relative);
    case Shape::plane: return plane_frame(shape.relative);
    case Shape::solid: break;
    }
    return shape.flat ? plane_frame(shape.relative) : solid_frame(points, seed);
}

OrientedBox fit_minimal_box(const Eigen::Matrix3d& axes, std::span<const Eigen::Vector3f> hull) {
    const OrientedBox box = fit_box(axes, hull);
    return with_min_thickness(box, std::max(1e-6f, 2e-4f * box.half_extents.maxCoeff()));
}

OrientedBox minimal_box(std::span<const Eigen::Vector3f> points, std::uint64_t seed) {
    const std::vector<Eigen::Vector3f> hull = hull_vertices(points);
    return fit_minimal_box(minimal_box_axes(hull_shape(hull), seed), hull);
}

}  // namespace boxlod
