// 3D Tiles 1.1 (OGC Community Standard, 2022) for a model of many objects, such
// as a city from `generate --city` (docs/design.md: Files). Each child of the
// root is an object with a chain of tiles, coarsest level first, each tile's
// only child its next finer level (REPLACE refinement) down to the original;
// glb content; the tileset placed on the WGS84 ellipsoid at a geodetic origin.
#pragma once
#include "toolkit/model/model.h"

#include <array>
#include <string>
#include <vector>

namespace boxlod {

struct Geodetic {
    double latitude_degrees = 49.0094, longitude_degrees = 8.4120,
           height = 0;  // default: KIT, Karlsruhe, home of the FZK-Haus
    // The model's north (+y of its file, a map grid's north) as an azimuth,
    // degrees clockwise from true north (map_projection.h).
    double heading_degrees = 0;
};

struct TileLevel {
    std::string content;           // the glb's URI, relative to the tileset
    double geometric_error;        // metres (level_geometric_error; 0 for the original)
    double surface_deviation = 0;  // metres (surface_deviation.h), written in the tile's extras
};

struct TileObject {
    std::string name;
    OrientedBox box;                // encloses every level (boxlod's box of the object's root)
    std::vector<TileLevel> levels;  // 0 (the original) .. N, each drawing other than the one before
};

// The tileset JSON. The root (ADD, no content) holds every object's chain; its
// geometric error is the objects' bounding sphere diameter, so a client opens
// it whenever the city is more than a few pixels tall, and at least twice each
// coarsest level's error, so a coarsest level is drawn over one doubling of
// distance as every other level is. A level's error is made at least that of
// every finer level, as refinement requires.
// `source_origin`: where the model's local origin lies in its file's
// coordinates (a city file's, z up; Model::origin), kept in the root's
// extras.boxlod.source_origin; the tiles are placed at `origin`, turned by its heading.
std::string tileset_json(const std::vector<TileObject>& objects, const Geodetic& origin,
                         const Eigen::Vector3d& source_origin = Eigen::Vector3d::Zero());

// The screen-space error, in pixels, at which 3D Tiles clients refine a tile
// by default (CesiumJS's maximumScreenSpaceError, 3d-tiles-renderer's errorTarget).
constexpr double client_screen_space_error = 16;

// The east-north-up frame at `at`, turned about up by its heading, in
// Earth-centred Earth-fixed metres (WGS84), column-major as 3D Tiles' `transform`.
std::array<double, 16> east_north_up_to_ecef(const Geodetic& at);

// A box in glTF's y-up frame as 3D Tiles' `boundingVolume.box` (z-up: glTF
// content is turned by +90 degrees about x, (x, y, z) -> (x, -z, y)): centre,
// then the three half-axis vectors. Half extents are at least 1 cm.
std::array<double, 12> tile_box(const OrientedBox& box);

}  // namespace boxlod
