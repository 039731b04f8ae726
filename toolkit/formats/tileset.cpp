#include "toolkit/formats/tileset.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace boxlod {
namespace {

constexpr double minimum_half_extent = 0.01;  // metres: clients reject flat boxes (the streets)

Eigen::Vector3d y_up_to_z_up(const Eigen::Vector3d& v) { return {v.x(), -v.z(), v.y()}; }

// A tile's children must not ask for more error than it: each level's error is
// at least that of every finer level.
std::vector<double> monotone_errors(const std::vector<TileLevel>& levels) {
    std::vector<double> errors;
    for (const TileLevel& level : levels)
        errors.push_back(std::max(level.geometric_error, errors.empty() ? 0.0 : errors.back()));
    return errors;
}

nlohmann::json object_chain(const TileObject& object) {
    const std::array<double, 12> box = tile_box(object.box);
    const std::vector<double> errors = monotone_errors(object.levels);
    nlohmann::json finer;
    for (std::size_t c = 0; c < object.levels.size(); ++c) {
        nlohmann::json tile = {{"boundingVolume", {{"box", box}}},
                               {"geometricError", errors[c]},
                               {"content", {{"uri", object.levels[c].content}}}};
        tile["extras"] = {{"boxlod", {{"surface_deviation", object.levels[c].surface_deviation}}}};
        if (c == object.levels.size() - 1) tile["extras"]["name"] = object.name;
        if (c > 0) {
            tile["refine"] = "REPLACE";
            tile["children"] = nlohmann::json::array({std::move(finer)});
        }
        finer = std::move(tile);
    }
    return finer;
}

}  // namespace

std::array<double, 12> tile_box(const OrientedBox& box) {
    std::array<double, 12> out{};
    const Eigen::Vector3d center = y_up_to_z_up(box.center.cast<double>());
    for (int i = 0; i < 3; ++i) out[std::size_t(i)] = center[i];
    for (int axis = 0; axis < 3; ++axis) {
        const double half = std::max(double(box.half_extents[axis]), minimum_half_extent);
        const Eigen::Vector3d v = y_up_to_z_up(box.axes.col(axis).cast<double>().normalized() * half);
        for (int i = 0; i < 3; ++i) out[std::size_t(3 + axis * 3 + i)] = v[i];
    }
    return out;
}

std::array<double, 16> east_north_up_to_ecef(const Geodetic& at) {
    // WGS84 (NIMA TR8350.2): semi-major axis a, first eccentricity squared e^2.
    const double a = 6378137.0, e2 = 6.69437999014e-3;
    const double phi = at.latitude_degrees * M_PI / 180, lambda = at.longitude_degrees * M_PI / 180;
    const double n =
        a / std::sqrt(1 - e2 * std::sin(phi) * std::sin(phi));  // prime vertical radius of curvature
    const Eigen::Vector3d origin((n + at.height) * std::cos(phi) * std::cos(lambda),
                                 (n + at.height) * std::cos(phi) * std::sin(lambda),
                                 (n * (1 - e2) + at.height) * std::sin(phi));
    const Eigen::Vector3d east(-std::sin(lambda), std::cos(lambda), 0);
    const Eigen::Vector3d north(-std::sin(phi) * std::cos(lambda), -std::sin(phi) * std::sin(lambda),
                                std::cos(phi));
    const Eigen::Vector3d up(std::cos(phi) * std::cos(lambda), std::cos(phi) * std::sin(lambda),
                             std::sin(phi));
    // The model's x and y axes: east and north turned clockwise by the heading.
    const double heading = at.heading_degrees * M_PI / 180;
    const Eigen::Vector3d x = std::cos(heading) * east - std::sin(heading) * north,
                          y = std::sin(heading) * east + std::cos(heading) * north;
    std::array<double, 16> m{};
    const Eigen::Vector3d* columns[4] = {&x, &y, &up, &origin};
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) m[std::size_t(c * 4 + r)] = (*columns[c])[r];
        m[std::size_t(c * 4 + 3)] = c == 3 ? 1 : 0;
    }
    return m;
}

std::string tileset_json(const std::vector<TileObject>& objects, const Geodetic& origin,
                         const Eigen::Vector3d& source_origin) {
    Bounds bounds;  // of every object's box, in the tiles' z-up frame
    for (const TileObject& object : objects) {
        const std::array<double, 12> b = tile_box(object.box);
        for (int corner = 0; corner < 8; ++corner) {
            Eigen::Vector3d p(b[0], b[1], b[2]);
            for (int axis = 0; axis < 3; ++axis)
                p += Eigen::Vector3d(b[3 + axis * 3], b[4 + axis * 3], b[5 + axis * 3]) *
                     ((corner >> axis) & 1 ? 1.0 : -1.0);
            bounds.add(p.cast<float>());
        }
    }
    const Eigen::Vector3d center = bounds.center().cast<double>(), half = bounds.size().cast<double>() / 2;
    // The root is refined while the city is more than a few pixels tall, and
    // at least as far as one doubling of distance beyond every coarsest
    // level's switch (where the next level would be), so those levels are
    // drawn over a range as every other level is.
    double root_error = 2 * half.norm();
    for (const TileObject& object : objects)
        root_error = std::max(root_error, 2 * monotone_errors(object.levels).back());
    nlohmann::json children = nlohmann::json::array();
    for (const TileObject& object : objects) children.push_back(object_chain(object));
    nlohmann::json root = {
        {"transform", east_north_up_to_ecef(origin)},
        {"boundingVolume",
         {{"box",
           {center.x(), center.y(), center.z(), std::max(half.x(), minimum_half_extent), 0, 0, 0,
            std::max(half.y(), minimum_half_extent), 0, 0, 0, std::max(half.z(), minimum_half_extent)}}}},
        {"geometricError", root_error},
        {"refine", "ADD"},
        {"children", std::move(children)},
    };
    if (!source_origin.isZero())
        root["extras"] = {
            {"boxlod", {{"source_origin", {source_origin.x(), source_origin.y(), source_origin.z()}}}}};
    nlohmann::json tileset = {{"asset", {{"version", "1.1"}, {"generator", "boxlod"}}},
                              {"geometricError", root_error},
                              {"root", std::move(root)}};
    return tileset.dump(1) + "\n";
}

}  // namespace boxlod
