#include "toolkit/selection/lod_switch.h"

#include <cmath>

namespace boxlod {

LodSwitch lod_switch(double distance, const Bounds& bounds, const TextureSizing& view) {
    const Eigen::Vector3d size = bounds.size().cast<double>();
    const double radius = size.norm() / 2, extent = size.maxCoeff();
    const double height = 2 * distance * std::tan(double(view.fovy_degrees) * M_PI / 360);
    LodSwitch s;
    s.distance = distance;
    s.screen_coverage = M_PI * radius * radius / (switch_screen_aspect * height * height);
    s.unity_relative_height = extent / height;
    s.unreal_screen_size = 2 * radius / height;
    return s;
}

}  // namespace boxlod
