// Checks on oriented boxes shared by the box tests.
#pragma once
#include "toolkit/model/model.h"

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

namespace boxlod::test {

inline bool encloses(const OrientedBox& box, const Eigen::Vector3f& p, double tolerance = 1e-5) {
    Eigen::Vector3d local =
        box.axes.cast<double>().transpose() * (p.cast<double>() - box.center.cast<double>());
    return (local.cwiseAbs().array() <= box.half_extents.cast<double>().array() + tolerance).all();
}

inline bool valid_frame(const OrientedBox& box) {
    return (box.axes.transpose() * box.axes).isApprox(Eigen::Matrix3f::Identity(), 1e-5f) &&
           std::abs(box.axes.determinant() - 1) < 1e-5f;
}

inline bool bitwise_equal(const OrientedBox& a, const OrientedBox& b) {
    return a.center == b.center && a.axes == b.axes && a.half_extents == b.half_extents;
}

inline bool bitwise_equal(const std::optional<OrientedBox>& a, const std::optional<OrientedBox>& b) {
    if (!a || !b) return !a && !b;
    return bitwise_equal(*a, *b);
}

}  // namespace boxlod::test
