#include "toolkit/formats/map_projection.h"

#include "base/input_error.h"
#include "base/key_values.h"

#include <proj.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

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

// The height of the geoid above the WGS 84 ellipsoid at a longitude and latitude
// (degrees), from EGM96's global grid in Debian's proj-data: NaN where it is missing.
double egm96_undulation(PJ_CONTEXT* context, const Eigen::Vector2d& longitude_latitude) {
    const Object shift(proj_create(context, "+proj=vgridshift +grids=egm96_15.gtx +multiplier=1"));
    if (!shift) return std::nan("");
    const PJ_COORD out =
        proj_trans(shift.get(), PJ_FWD,
                   proj_coord(proj_torad(longitude_latitude.x()), proj_torad(longitude_latitude.y()), 0, 0));
    return std::abs(out.xyz.z) < 200 ? out.xyz.z : std::nan("");  // |N| < 110 m on the Earth
}

// A compound system's height (above its geoid, `heights` its vertical part) made a height above
// the ellipsoid, by EGM96's geoid; false where the grid is missing.
bool add_geoid(PJ_CONTEXT* context, PJ* heights, MapPlacement& placement) {
    const double undulation =
        egm96_undulation(context, {placement.at.longitude_degrees, placement.at.latitude_degrees});
    if (!std::isfinite(undulation)) return false;
    placement.at.height += undulation;
    const char* name = proj_get_name(heights);
    placement.operation += std::string(" + ") + (name ? name : "heights") + " by EGM96's geoid";
    return true;
}

// A coordinate system's axes: where each points ("east", "north", "up", ...; "" where PROJ does
// not say) and its metres per unit.
struct Axis {
    std::string direction;
    double metres = 0;
};
std::vector<Axis> axes_of(PJ_CONTEXT* context, PJ* system) {
    const Object axes(proj_crs_get_coordinate_system(context, system));
    const int axis_count = axes ? proj_cs_get_axis_count(context, axes.get()) : 0;
    std::vector<Axis> out;
    for (int axis = 0; axis < axis_count; ++axis) {
        const char* direction = nullptr;
        double metres = 0;
        proj_cs_get_axis_info(context, axes.get(), axis, nullptr, nullptr, &direction, &metres, nullptr,
                              nullptr, nullptr);
        out.push_back({direction ? direction : "", metres});
    }
    return out;
}

bool in_metres(const std::vector<Axis>& axes) {
    return std::all_of(axes.begin(), axes.end(), [](const Axis& a) { return a.metres == 1; });
}

bool points(const std::vector<Axis>& axes, const std::string& direction) {
    return std::any_of(axes.begin(), axes.end(), [&](const Axis& a) { return a.direction == direction; });
}

}  // namespace

// The azimuth from true north, degrees, of `to` seen from `from` (longitudes and latitudes, on the sphere).
double azimuth(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    const double east = std::remainder(to.x() - from.x(), 360.0) * std::cos(from.y() * M_PI / 180);
    return std::atan2(east, to.y() - from.y()) * 180 / M_PI;
}

// Far outside where a projection is meant for it still gives a place (RD New at 9e8 m: 51.6 S, 176 W;
// Web Mercator at 1e11 m: the pole): whether `point`, at `longitude_latitude`, comes back from WGS 84
// within a kilometre and lies within the system's area of use (EPSG's, as PROJ gives it; across the
// antimeridian west > east) and 5 degrees around it.
bool meant_for(PJ_CONTEXT* context, PJ* system, PJ* to_wgs84, const Eigen::Vector3d& point,
               const Eigen::Vector2d& longitude_latitude) {
    constexpr double margin = 5;
    const PJ_COORD back =
        proj_trans(to_wgs84, PJ_INV, proj_coord(longitude_latitude.x(), longitude_latitude.y(), 0, 0));
    if (!(std::hypot(back.xy.x - point.x(), back.xy.y - point.y()) <= 1000)) return false;
    double west = 0, south = 0, east = 0, north = 0;
    if (!proj_get_area_of_use(context, system, &west, &south, &east, &north, nullptr) || west < -180)
        return true;
    const double longitude = longitude_latitude.x(), latitude = longitude_latitude.y();
    const bool in_longitude = west <= east ? longitude >= west - margin && longitude <= east + margin
                                           : longitude >= west - margin || longitude <= east + margin;
    return in_longitude && latitude >= south - margin && latitude <= north + margin;
}

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
    Object heights;  // a compound system's vertical part: heights above its geoid
    if (proj_get_type(system.get()) == PJ_TYPE_COMPOUND_CRS) {
        heights.reset(proj_crs_get_sub_crs(context.get(), system.get(), 1));
        system.reset(proj_crs_get_sub_crs(context.get(), system.get(), 0));
        if (heights && proj_get_type(heights.get()) == PJ_TYPE_BOUND_CRS)  // a WKT 1 height with its grid
            heights.reset(proj_get_source_crs(context.get(), heights.get()));
        if (heights && proj_get_type(heights.get()) != PJ_TYPE_VERTICAL_CRS)
            fail("its heights are not heights");
        const std::vector<Axis> vertical =
            heights ? axes_of(context.get(), heights.get()) : std::vector<Axis>{};
        if (heights && (!in_metres(vertical) || !points(vertical, "up")))
            fail("its heights are not metres up");
    }
    // The model's coordinates are metres east and north: a map grid in metres.
    if (!system || proj_get_type(system.get()) != PJ_TYPE_PROJECTED_CRS)
        fail("not a projected system (x east, y north in metres)");
    const std::vector<Axis> axes = axes_of(context.get(), system.get());
    if (axes.size() < 2) fail("PROJ gives no axes for it");
    if (!in_metres(axes)) fail("its units are not metres");
    // normalize_for_visualization below orders the axes, but does not turn a southing or westing.
    if (!points(axes, "east") || !points(axes, "north")) fail("its axes do not point east and north");
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
    if (!meant_for(context.get(), system.get(), to_wgs84.get(), point, here))
        fail("the model's origin (" + format_number(point.x()) + ", " + format_number(point.y()) +
             ") lies outside where it is meant for (at longitude " + format_number(here.x()) + ", latitude " +
             format_number(here.y()) + ")");
    MapPlacement placement;
    placement.at.latitude_degrees = here.y();
    placement.at.longitude_degrees = here.x();
    placement.at.heading_degrees = azimuth(here, north);
    const PJ_PROJ_INFO info = proj_pj_info(to_wgs84.get());
    placement.operation = info.description ? info.description : "";
    placement.at.height = point.z();
    if (heights && !add_geoid(context.get(), heights.get(), placement))
        fail("EGM96's geoid grid (egm96_15.gtx, Debian's proj-data) is missing");
    return placement;
}

}  // namespace boxlod
