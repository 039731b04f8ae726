#include "toolkit/model/framing.h"

#include <algorithm>

namespace boxlod {

Framing framing_of(const Bounds& bounds) {
    return {bounds.center(), std::max(bounds.size().norm() / 2, 1e-6f)};
}

Framing model_framing(const Model& model) { return framing_of(model_bounds(model)); }

float framing_distance(const Framing& framing, float fovy_degrees) {
    return framing_distance(framing.radius, fovy_degrees);
}

Camera framed_camera(const Framing& framing, const Eigen::Vector3f& direction, float distance,
                     float fovy_degrees) {
    return camera_at_position(direction, framing.center, distance, fovy_degrees, framing.radius);
}

}  // namespace boxlod
