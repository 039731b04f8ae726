#include "toolkit/cgal/polygon_triangulation.h"

#include <Eigen/Geometry>  // cross products

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <deque>
#include <limits>

namespace boxlod {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr std::uint32_t no_index = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t most_crossings = 64;  // beyond as many as the rings have points
struct VertexInfo {
    std::uint32_t index = no_index;  // into the rings' points; no_index: where two rings cross
};
struct FaceInfo {
    int nesting = -1;  // rings crossed from outside; odd: inside the polygon
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using FaceBase =
    CGAL::Constrained_triangulation_face_base_2<Kernel,
                                                CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Exact predicates: rings that cross are split where they meet (at an approximate point).
using Triangulation =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, DataStructure, CGAL::Exact_predicates_tag>;
using Face = Triangulation::Face_handle;

// Flood fill from `start` over unconstrained edges, setting `nesting`; the
// constrained edges met lead to the next level.
void fill_domain(Triangulation& triangulation, Face start, int nesting,
                 std::deque<Triangulation::Edge>& border) {
    std::deque<Face> queue{start};
    while (!queue.empty()) {
        Face face = queue.front();
        queue.pop_front();
        if (face->info().nesting != -1) continue;
        face->info().nesting = nesting;
        for (int i = 0; i < 3; ++i) {
            Face neighbor = face->neighbor(i);
            if (neighbor->info().nesting != -1) continue;
            if (triangulation.is_constrained({face, i}))
                border.emplace_back(face, i);
            else
                queue.push_back(neighbor);
        }
    }
}

void mark_nesting(Triangulation& triangulation) {
    std::deque<Triangulation::Edge> border;
    fill_domain(triangulation, triangulation.infinite_face(), 0, border);
    while (!border.empty()) {
        auto [face, i] = border.front();
        border.pop_front();
        Face next = face->neighbor(i);
        if (next->info().nesting == -1) fill_domain(triangulation, next, face->info().nesting + 1, border);
    }
}

}  // namespace

Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& ring) {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < ring.size(); ++i) normal += ring[i].cross(ring[(i + 1) % ring.size()]);
    return normal;
}

PolygonTriangles triangulate_polygon(const std::vector<std::vector<Eigen::Vector3d>>& rings) {
    PolygonTriangles out;
    if (rings.empty() || rings[0].size() < 3) return out;
    // Relative to the first point: Newell's sum and the projection stay exact for far-away rings.
    const Eigen::Vector3d anchor = rings[0][0];
    std::vector<Eigen::Vector3d> outer;
    for (const Eigen::Vector3d& p : rings[0]) outer.push_back(p - anchor);
    const Eigen::Vector3d normal = newell_normal(outer);
    if (!normal.allFinite() || !(normal.norm() > 0) || !std::isfinite(normal.norm())) return out;
    // A right-handed basis (u, v, normal): counter-clockwise in (u, v) turns about the normal.
    const Eigen::Vector3d w = normal.normalized();
    const Eigen::Vector3d u = w.unitOrthogonal(), v = w.cross(u);
    Triangulation triangulation;
    std::uint32_t index = 0;
    for (const auto& ring : rings) {
        std::vector<Triangulation::Vertex_handle> vertices;
        for (const Eigen::Vector3d& p : ring) {
            const Eigen::Vector3d d = p - anchor;
            auto vertex = triangulation.insert(Kernel::Point_2(d.dot(u), d.dot(v)));
            if (vertex->info().index == no_index)
                vertex->info().index = index;  // a repeated point keeps its first index
            ++index;
            vertices.push_back(vertex);
        }
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            auto a = vertices[i], b = vertices[(i + 1) % vertices.size()];
            if (a != b) triangulation.insert_constraint(a, b);
            // Crossings grow as the square of the points: a ring wound as a star would fill the memory.
            if (triangulation.number_of_vertices() > 2 * std::size_t(index) + most_crossings) {
                out.too_many_crossings = true;
                return out;
            }
        }
    }
    mark_nesting(triangulation);
    for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face) {
        if (face->info().nesting % 2 != 1) continue;
        std::array<std::uint32_t, 3> triangle;
        for (int i = 0; i < 3; ++i) {
            VertexInfo& info = face->vertex(i)->info();
            if (info.index == no_index) {  // where rings cross: lifted back onto the plane
                const auto& p = face->vertex(i)->point();
                info.index = index + std::uint32_t(out.added_points.size());
                out.added_points.push_back(anchor + CGAL::to_double(p.x()) * u + CGAL::to_double(p.y()) * v);
            }
            triangle[i] = info.index;
        }
        out.triangles.push_back(triangle);
    }
    return out;
}

}  // namespace boxlod
