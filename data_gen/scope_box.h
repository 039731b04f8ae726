// The scope as the interpreter works with it: a corner `origin`, three
// orthonormal `axes` (columns) and a `size` along them, as in CGA. Stored in
// the model as a boxlod::Scope (center and half-extents).
#pragma once
#include "toolkit/model/model.h"

#include <Eigen/Core>

namespace boxlod {

struct ScopeBox {
    Eigen::Vector3f origin = Eigen::Vector3f::Zero();
    Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();
    Eigen::Vector3f size = Eigen::Vector3f::Zero();

    Eigen::Vector3f center() const { return origin + axes * (size / 2); }
    // A point given in the scope's own metres, in world space.
    Eigen::Vector3f to_world(const Eigen::Vector3f& local) const { return origin + axes * local; }
};

inline Scope to_scope(const ScopeBox& box) {
    Scope scope;
    scope.center = box.center();
    scope.axes = box.axes;
    scope.half_extents = box.size / 2;
    return scope;
}

}  // namespace boxlod
