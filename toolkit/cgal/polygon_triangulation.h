// Planar polygons with holes in 3D as triangles: CGAL's constrained Delaunay
// triangulation of the rings projected on the polygon's plane, keeping the
// triangles inside an odd number of rings (CGAL manual, 2D Triangulations:
// "Triangulating a Polygonal Domain"). For CityJSON and other surface
// formats that store polygons with holes (toolkit/formats/cityjson_import.h).
#pragma once
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace boxlod {

// rings[0] is the outer boundary, the others holes; orientation is free.
// Triangles index the rings' points in order (ring 0's first, then ring 1's,
// ...), then `added_points` where crossing rings meet; each triangle turns
// as the outer ring does (counter-clockwise about the polygon's normal by
// Newell's method). A polygon without area gives no triangle; one whose rings
// cross more often than they have points (and 64) none either, and says so.
struct PolygonTriangles {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<Eigen::Vector3d> added_points;
    bool too_many_crossings = false;
};
PolygonTriangles triangulate_polygon(const std::vector<std::vector<Eigen::Vector3d>>& rings);

// The normal of a closed ring by Newell's method (not normalised; zero for a
// ring without area).
Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& ring);

}  // namespace boxlod
