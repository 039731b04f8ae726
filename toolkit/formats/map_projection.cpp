#include "toolkit/formats/map_projection.h"

#include "base/input_error.h"

#include <proj.h>

#include <cmath>
#include <memory>
#include <set>
#include <string>

namespace boxlod {
namespace {

struct ContextDeleter {
    void operator()(PJ_CONTEXT* c) const { proj_context_destroy(c); }
};
struct ObjectDeleter {
    void operator()(PJ* p) const { proj_destroy(p); }
};
using Context = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using Object = std::unique_ptr<PJ, ObjectDeleter>;

// Longitude and latitude in degrees of (x, y) of the transformation's source.
Eigen::Vector2d longitude_latitude(PJ* to_wgs84, double x, double y) {
    const PJ_COORD out = proj_trans(to_wgs84, PJ_FWD, proj_coord(x, y, 0, 0));
    return {out.xy.x, out.xy.y};
}

}  // namespace

MapPlacement place_on_earth(const std::string& reference_system, const Eigen::Vector3d& point,
                            const std::string& source) {
    auto fail = [&](const std::string& what) {
        throw_input_error(source, "",
                          "reference system '" + reference_system + "': " + what +
                              " (give --latitude and --longitude instead)");
    };
    const Context context(proj_context_create());
    proj_log_level(context.get(), PJ_LOG_NONE);             // its messages are ours to word
    proj_context_set_enable_network(context.get(), false);  // the same answer everywhere, offline
    Object system(proj_create(context.get(), reference_system.c_str()));
    if (!system || !proj_is_crs(system.get())) fail("not a reference system PROJ knows");
    if (proj_get_type(system.get()) == PJ_TYPE_COMPOUND_CRS)
        system.reset(proj_crs_get_sub_crs(context.get(), system.get(), 0));
    // The model's coordinates are metres east and north: a map grid in metres.
    if (!system || proj_get_type(system.get()) != PJ_TYPE_PROJECTED_CRS)
        fail("not a projected system (x east, y north in metres)");
    const Object axes(proj_crs_get_coordinate_system(context.get(), system.get()));
    const int axis_count = axes ? proj_cs_get_axis_count(context.get(), axes.get()) : -1;
    if (axis_count < 2) fail("PROJ gives no axes for it");
    std::set<std::string> directions;
    for (int axis = 0; axis < axis_count; ++axis) {
        const char* direction = nullptr;
        double metres_per_unit = 0;
        proj_cs_get_axis_info(context.get(), axes.get(), axis, nullptr, nullptr, &direction, &metres_per_unit,
                              nullptr, nullptr, nullptr);
        if (metres_per_unit != 1) fail("its units are not metres");
        if (direction) directions.insert(direction);
    }
    // normalize_for_visualization below orders the axes, but does not turn a southing or westing.
    if (!directions.count("east") || !directions.count("north")) fail("its axes do not point east and north");
    const Object wgs84(proj_create(context.get(), "EPSG:4326"));
    Object raw(
        wgs84 ? proj_create_crs_to_crs_from_pj(context.get(), system.get(), wgs84.get(), nullptr, nullptr)
              : nullptr);
    // Longitude first, whatever the systems' axis order.
    const Object to_wgs84(raw ? proj_normalize_for_visualization(context.get(), raw.get()) : nullptr);
    if (!to_wgs84) fail("PROJ has no transformation from it to WGS 84");
    // The grid's north: the point a kilometre up its y axis, as an azimuth from true north
    // (on the sphere; the convergence changes little over a kilometre).
    const Eigen::Vector2d here = longitude_latitude(to_wgs84.get(), point.x(), point.y()),
                          north = longitude_latitude(to_wgs84.get(), point.x(), point.y() + 1000);
    if (!here.allFinite() || !north.allFinite() || std::abs(here.y()) > 90 || std::abs(north.y()) > 90)
        fail("the model's origin does not transform to WGS 84");
    const double phi = here.y() * M_PI / 180;
    const double east = std::remainder(north.x() - here.x(), 360.0) * std::cos(phi),
                 up_north = north.y() - here.y();
    MapPlacement placement;
    placement.at.latitude_degrees = here.y();
    placement.at.longitude_degrees = here.x();
    placement.at.height = point.z();
    placement.at.heading_degrees = std::atan2(east, up_north) * 180 / M_PI;
    const PJ_PROJ_INFO info = proj_pj_info(to_wgs84.get());
    placement.operation = info.description ? info.description : "";
    return placement;
}

}  // namespace boxlod
