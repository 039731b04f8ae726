#include "toolkit/cgal/box_fit.h"

#include <Eigen/Dense>  // cross products, determinants

#include <algorithm>
#include <cmath>
#include <limits>

namespace boxlod {

namespace {

// A unit vector perpendicular to the unit vector `a`: its cross product with
// the world axis least aligned with it (never parallel).
Eigen::Vector3d perpendicular(const Eigen::Vector3d& a) {
    Eigen::Index k = 0;
    a.cwiseAbs().minCoeff(&k);
    return a.cross(Eigen::Vector3d::Unit(k)).normalized();
}

}  // namespace

Eigen::Matrix3d orthonormal_frame(const Eigen::Matrix3d& axes) {
    const double tiny = 1e-12;
    Eigen::Vector3d a0 = axes.col(0);
    double n0 = a0.norm();
    a0 = n0 > tiny && std::isfinite(n0) ? Eigen::Vector3d(a0 / n0) : Eigen::Vector3d::UnitX();
    Eigen::Vector3d c1 = axes.col(1);
    Eigen::Vector3d a1 = c1 - a0.dot(c1) * a0;
    double n1 = a1.norm();
    if (n1 > tiny * std::max(1.0, c1.norm()) && std::isfinite(n1)) {
        a1 /= n1;
        a1 -= a0.dot(a1) * a0;  // a second Gram-Schmidt pass removes the first pass's rounding
        a1.normalize();
    } else {
        a1 = perpendicular(a0);
    }
    Eigen::Matrix3d frame;
    frame << a0, a1, a0.cross(a1).normalized();  // right-handed by construction
    return frame;
}

OrientedBox fit_box(const Eigen::Matrix3d& axes, std::span<const Eigen::Vector3f> points) {
    // Scalar code, and rounded values kept in locals instead of read back from
    // the box: GCC 12's vectorizer dropped the float rounding of such
    // store-then-reload round trips (double -> float -> double), which broke enclosure.
    // Re-checked once the one-definition rule held (docs/testing.md: Determinism): the Eigen form
    // still fails BoxFit.FitBoxEnclosesAfterRounding at -O2 and passes with
    // -fno-tree-vectorize: the vectorizer, not a one-definition-rule violation.
    double a[3][3];  // the float axes that are stored, as doubles (float products are exact there)
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) {
            const float rounded = float(axes(r, k));
            a[r][k] = double(rounded);
        }
    auto project = [&](const Eigen::Vector3f& p, const double origin[3], int k) {
        return a[0][k] * (double(p.x()) - origin[0]) + a[1][k] * (double(p.y()) - origin[1]) +
               a[2][k] * (double(p.z()) - origin[2]);
    };
    const double zero[3] = {0, 0, 0};
    const double inf = std::numeric_limits<double>::infinity();
    double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
    for (const Eigen::Vector3f& p : points)
        for (int k = 0; k < 3; ++k) {
            const double q = project(p, zero, k);
            lo[k] = std::min(lo[k], q);
            hi[k] = std::max(hi[k], q);
        }
    double c[3] = {0, 0, 0};
    for (int r = 0; r < 3 && !points.empty(); ++r) {
        double mid = 0;
        for (int k = 0; k < 3; ++k) mid += a[r][k] * ((lo[k] + hi[k]) / 2);
        const float rounded = float(mid);
        c[r] = double(rounded);
    }
    // Half-extents around the rounded centre, rounded up: the float box encloses every point.
    float half[3];
    for (int k = 0; k < 3; ++k) {
        double extent = 0;
        for (const Eigen::Vector3f& p : points) extent = std::max(extent, std::abs(project(p, c, k)));
        half[k] = float(extent);
        if (double(half[k]) < extent)
            half[k] = std::nextafter(half[k], std::numeric_limits<float>::infinity());
    }
    OrientedBox box;
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) box.axes(r, k) = float(a[r][k]);
        box.center[r] = float(c[r]);
        box.half_extents[r] = half[r];
    }
    return box;
}

OrientedBox with_min_thickness(OrientedBox box, float thickness) {
    box.half_extents = box.half_extents.cwiseMax(Eigen::Vector3f::Constant(thickness / 2));
    return box;
}

std::array<Eigen::Vector3f, 8> box_corners(const OrientedBox& box) {
    std::array<Eigen::Vector3f, 8> corners;
    for (int i = 0; i < 8; ++i) {
        Eigen::Vector3f sign(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : -1.f);
        corners[i] = box.center + box.axes * sign.cwiseProduct(box.half_extents);
    }
    return corners;
}

}  // namespace boxlod
