#include "toolkit/lod/chain/switch_measures.h"

#include "toolkit/formats/tileset.h"
#include "toolkit/model/framing.h"

#include <algorithm>
#include <cmath>

namespace boxlod {

LodSwitch lod_switch(double distance, const Bounds& bounds, const TextureSizing& view) {
    const double radius = framing_of(bounds).radius, extent = bounds.size().maxCoeff();
    const double height = 2 * distance * std::tan(double(view.fovy_degrees) * M_PI / 360);
    LodSwitch s;
    s.distance = distance;
    s.screen_coverage = M_PI * radius * radius / (switch_screen_aspect * height * height);
    s.unity_relative_height = extent / height;
    s.unreal_screen_size = 2 * radius / height;
    return s;
}

double level_geometric_error(double switch_distance, const TextureSizing& view, double surface_deviation) {
    TextureSizing at = view;
    at.distance = float(switch_distance);
    return std::max(surface_deviation, client_screen_space_error * pixel_world_size(at));
}

}  // namespace boxlod
