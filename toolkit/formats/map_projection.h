// Where a city file's coordinates lie on the Earth: its reference system
// (CityJSON's metadata.referenceSystem, e.g. EPSG 7415, the Netherlands' RD
// New + NAP) to WGS 84 latitude and longitude through PROJ, so that `tiles`
// places a district where it is (docs/city.md: Viewing a city as 3D Tiles).
#pragma once
#include "toolkit/formats/tileset.h"

#include <Eigen/Core>

#include <string>

namespace boxlod {

// What PROJ makes of `point` (x east, y north, z up, in the reference system's
// units) of the reference system named `reference_system` (EPSG:7415,
// urn:ogc:def:crs:EPSG::7415 or https://www.opengis.net/def/crs/EPSG/0/7415):
// its latitude and longitude on WGS 84, its height above the WGS 84 ellipsoid
// (a compound system's heights, above its geoid, plus EGM96's geoid there:
// Debian's proj-data has EGM96's global grid but not the height systems' own,
// as NAP's NLGEO2018; a projected system's as the file gives it), and the heading of the map grid's north
// there (meridian convergence), so that the model's axes are turned as the grid is. A compound system is
// taken by its horizontal part, as PROJ's transformation of the whole falls back to a ballpark offset (about
// 100 m in the Netherlands). `operation`: PROJ's description of the transformation used. Throws InputError
// naming `source` when PROJ does not know the system, when it is not a projected system in metres (a
// geographic or geocentric one, a grid in feet: the model's coordinates would not be metres east and north),
// when a compound system's heights are not metres up (feet, depths), when EGM96's grid is missing,
// or when the point does not transform.
struct MapPlacement {
    Geodetic at;
    std::string operation;
};
MapPlacement place_on_earth(const std::string& reference_system, const Eigen::Vector3d& point,
                            const std::string& source);

}  // namespace boxlod
