#include "toolkit/cgal/cgal_simplification.h"

#include "base/input_error.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace boxlod {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;

// What a vertex carries besides its position.
struct Attributes {
    Eigen::Vector2f uv = Eigen::Vector2f::Zero();
    Eigen::Vector4f tangent = Eigen::Vector4f::Zero();
};
using Key = std::array<float, 3>;
Key key_of(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }

// Edge_collapse counts edges; the budget is faces.
struct FaceCountStop {
    const Mesh* mesh;
    std::size_t target;
    template <typename Profile>
    bool operator()(const double&, const Profile&, std::size_t, std::size_t) const {
        return mesh->number_of_faces() <= target;
    }
};

struct Part {
    int material = -1;
    bool uvs = false, tangents = false;
    std::vector<Point> points;
    std::vector<std::array<std::size_t, 3>> triangles;
    std::map<Key, Attributes> attributes;  // the first vertex at each position
    double area = 0;
};

// Each material's triangles as a soup welded by position (one part per material).
std::vector<Part> parts_of(const Model& model) {
    std::map<int, std::size_t> index;
    std::vector<Part> parts;
    std::vector<std::map<Key, std::size_t>> welded;
    for (const Node& node : model.nodes)
        for (const Primitive& p : node.primitives) {
            if (p.indices.empty()) continue;
            auto [it, added] = index.try_emplace(p.material, parts.size());
            if (added) {
                parts.push_back({});
                parts.back().material = p.material;
                welded.emplace_back();
            }
            Part& part = parts[it->second];
            part.uvs = part.uvs || !p.uvs.empty();
            part.tangents = part.tangents || !p.tangents.empty();
            std::vector<std::size_t> point_of(p.positions.size());
            for (std::size_t v = 0; v < p.positions.size(); ++v) {
                auto [at, fresh] = welded[it->second].try_emplace(key_of(p.positions[v]), part.points.size());
                if (fresh) {
                    part.points.emplace_back(p.positions[v].x(), p.positions[v].y(), p.positions[v].z());
                    Attributes a;
                    if (!p.uvs.empty()) a.uv = p.uvs[v];
                    if (!p.tangents.empty()) a.tangent = p.tangents[v];
                    part.attributes.emplace(key_of(p.positions[v]), a);
                }
                point_of[v] = at->second;
            }
            for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) {
                part.triangles.push_back(
                    {point_of[p.indices[i]], point_of[p.indices[i + 1]], point_of[p.indices[i + 2]]});
                const Eigen::Vector3f &a = p.positions[p.indices[i]], &b = p.positions[p.indices[i + 1]],
                                      &c = p.positions[p.indices[i + 2]];
                part.area += 0.5 * double((b - a).cross(c - a).norm());
            }
        }
    return parts;
}

// The part collapsed to `target` triangles (or as far as CGAL goes), flat-shaded.
Primitive simplify_part(Part part, std::size_t target) {
    PMP::repair_polygon_soup(part.points, part.triangles);
    PMP::orient_polygon_soup(part.points, part.triangles);
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(part.points, part.triangles, mesh);
    // Each vertex's attributes, by its position before collapsing moves it.
    auto [carried, added] =
        mesh.add_property_map<Mesh::Vertex_index, Attributes>("v:attributes", Attributes{});
    for (Mesh::Vertex_index v : mesh.vertices()) {
        const Point& p = mesh.point(v);
        auto found = part.attributes.find({float(p.x()), float(p.y()), float(p.z())});
        if (found != part.attributes.end()) carried[v] = found->second;
    }
    if (mesh.number_of_faces() > target) {
        SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(mesh);
        SMS::edge_collapse(
            mesh, FaceCountStop{&mesh, target},
            CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
    }
    Primitive out;
    out.material = part.material;
    // Vertices equal in every attribute are shared, as an exporter would write them.
    std::map<std::array<float, 12>, std::uint32_t> shared;
    auto add_vertex = [&](const Eigen::Vector3f& position, const Eigen::Vector3f& normal,
                          const Attributes& a) {
        std::array<float, 12> key = {position.x(),  position.y(),  position.z(),  normal.x(),
                                     normal.y(),    normal.z(),    a.uv.x(),      a.uv.y(),
                                     a.tangent.x(), a.tangent.y(), a.tangent.z(), a.tangent.w()};
        auto [at, added] = shared.try_emplace(key, std::uint32_t(out.positions.size()));
        if (added) {
            out.positions.push_back(position);
            out.normals.push_back(normal);
            if (part.uvs) out.uvs.push_back(a.uv);
            if (part.tangents) out.tangents.push_back(a.tangent);
        }
        out.indices.push_back(at->second);
    };
    for (Mesh::Face_index f : mesh.faces()) {
        std::array<Eigen::Vector3f, 3> corners;
        std::array<Mesh::Vertex_index, 3> vertices;
        int k = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            if (k == 3) break;
            const Point& p = mesh.point(v);
            corners[std::size_t(k)] = Eigen::Vector3f(float(p.x()), float(p.y()), float(p.z()));
            vertices[std::size_t(k++)] = v;
        }
        Eigen::Vector3f normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
        if (k != 3 || !(normal.squaredNorm() > 0)) continue;  // degenerate after collapsing
        normal.normalize();
        for (int c = 0; c < 3; ++c)
            add_vertex(corners[std::size_t(c)], normal, carried[vertices[std::size_t(c)]]);
    }
    out.polygon_count = out.triangle_count();
    return out;
}

}  // namespace

Model cgal_simplify(const Model& model, std::size_t target_faces) {
    if (model.is_lod)
        throw_input_error(model.source, "simplify", "an LoD that boxlod exported cannot be simplified again");
    if (target_faces == 0) throw_input_error(model.source, "simplify", "the face target must be at least 1");
    std::vector<Part> parts = parts_of(model);
    if (parts.empty()) throw_input_error(model.source, "simplify", "the model has no triangles");
    double area = 0;
    for (const Part& part : parts) area += part.area;

    Model result;
    keep_provenance(model, result);
    result.materials = model.materials;
    result.textures = model.textures;
    add_node(result, -1, model.nodes.empty() ? "simplified" : model.nodes[0].name);
    for (Part& part : parts) {
        // By area, at least one triangle: the walls keep theirs (simplification.h: by-area).
        double share = area > 0 ? part.area / area : 1.0 / double(parts.size());
        auto target = std::size_t(std::max(1.0, std::floor(double(target_faces) * share)));
        Primitive mesh = simplify_part(std::move(part), target);
        if (mesh.indices.empty()) continue;
        int material = mesh.material;
        int n = add_node(result, 0,
                         material >= 0 ? model.materials[std::size_t(material)].name : "default material");
        result.nodes[std::size_t(n)].primitives.push_back(std::move(mesh));
    }
    return result;
}

}  // namespace boxlod
