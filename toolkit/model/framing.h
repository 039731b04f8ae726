// Framing a model (docs/design.md: Rendering): the camera positions look at
// the centre of the model's bounding box, and the default distance fits its
// bounding sphere (radius half the box's diagonal) into the field of view.
// Every command, the sweep, the LoD preview and the viewer frame this way.
#pragma once
#include "renderer/camera.h"
#include "toolkit/model/model.h"

#include <Eigen/Core>

namespace boxlod {

struct Framing {
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
    float radius = 1e-6f;  // half the bounding box's diagonal, at least 1e-6
};

Framing framing_of(const Bounds& bounds);
Framing model_framing(const Model& model);

// The distance at which the bounding sphere fills `fovy_degrees`, with a margin.
float framing_distance(const Framing& framing, float fovy_degrees);

// The camera at `distance` from the centre along `direction` (one of the 26
// positions of camera_direction, or any), near and far fitted to the sphere.
Camera framed_camera(const Framing& framing, const Eigen::Vector3f& direction, float distance,
                     float fovy_degrees);

}  // namespace boxlod
