#include "data_gen/primitives.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace boxlod {

using Eigen::Vector3f;

std::array<ScopeFace, 6> scope_faces(const Vector3f& s) {
    const Vector3f x = Vector3f::UnitX(), y = Vector3f::UnitY(), z = Vector3f::UnitZ();
    return {{
        {"front", Vector3f(0, 0, s.z()), x, y, s.x(), s.y()},
        {"right", Vector3f(s.x(), 0, s.z()), -z, y, s.z(), s.y()},
        {"back", Vector3f(s.x(), 0, 0), -x, y, s.x(), s.y()},
        {"left", Vector3f(0, 0, 0), z, y, s.z(), s.y()},
        {"top", Vector3f(0, s.y(), s.z()), x, -z, s.x(), s.z()},
        {"bottom", Vector3f(0, 0, 0), x, z, s.x(), s.z()},
    }};
}

namespace {

const char* const primitive_names[] = {"box", "quad", "cylinder", "gable", "hip"};

void add_rectangle(Primitive& primitive, const Vector3f& origin, const Vector3f& u, const Vector3f& v) {
    add_polygon(primitive, {origin, origin + u, origin + u + v, origin + v});
}

void add_cylinder(Primitive& primitive, const Vector3f& s, int segments) {
    float rx = s.x() / 2, rz = s.z() / 2;
    auto rim = [&](int k, float height) {
        double angle = 2 * std::numbers::pi * (k % segments) / segments;
        return Vector3f(rx + rx * float(std::cos(angle)), height, rz + rz * float(std::sin(angle)));
    };
    auto outward = [&](int k) {
        double angle = 2 * std::numbers::pi * (k % segments) / segments;
        return Vector3f(rz * float(std::cos(angle)), 0, rx * float(std::sin(angle))).normalized();
    };
    for (int k = 0; k < segments; ++k)
        add_polygon(primitive, {rim(k + 1, 0), rim(k, 0), rim(k, s.y()), rim(k + 1, s.y())},
                    {outward(k + 1), outward(k), outward(k), outward(k + 1)});
    std::vector<Vector3f> top, bottom;
    for (int k = 0; k < segments; ++k) {
        bottom.push_back(rim(k, 0));
        top.push_back(rim(segments - k, s.y()));
    }
    add_polygon(primitive, top);
    add_polygon(primitive, bottom);
}

void add_gable(Primitive& primitive, const Vector3f& s) {
    float w = s.x(), h = s.y(), d = s.z();
    Vector3f ridge_left(0, h, d / 2), ridge_right(w, h, d / 2);
    add_polygon(primitive, {{0, 0, d}, {w, 0, d}, ridge_right, ridge_left});
    add_polygon(primitive, {{w, 0, 0}, {0, 0, 0}, ridge_left, ridge_right});
    add_polygon(primitive, {{w, 0, d}, {w, 0, 0}, ridge_right});
    add_polygon(primitive, {{0, 0, 0}, {0, 0, d}, ridge_left});
    add_polygon(primitive, {{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}});
}

void add_hip(Primitive& primitive, const Vector3f& s) {
    // Built with the ridge along x for a roof `long_side` by `short_side`,
    // then turned a quarter around y when the scope is deeper than wide.
    bool turned = s.z() > s.x();
    float w = turned ? s.z() : s.x(), d = turned ? s.x() : s.z(), h = s.y(), r = d / 2;
    auto place = [&](float x, float y, float z) {
        return turned ? Vector3f(z, y, w - x) : Vector3f(x, y, z);
    };
    Vector3f a = place(0, 0, 0), b = place(w, 0, 0), c = place(w, 0, d), e = place(0, 0, d);
    Vector3f ridge_left = place(r, h, d / 2), ridge_right = place(w - r, h, d / 2);
    add_polygon(primitive, {e, c, ridge_right, ridge_left});
    add_polygon(primitive, {b, a, ridge_left, ridge_right});
    add_polygon(primitive, {c, b, ridge_right});
    add_polygon(primitive, {a, e, ridge_left});
    add_polygon(primitive, {a, b, c, e});
}

}  // namespace

bool is_builtin_primitive(const std::string& name) {
    for (const char* known : primitive_names)
        if (name == known) return true;
    return false;
}

std::string builtin_primitive_names() { return "box, quad, cylinder, gable, hip"; }

void add_polygon(Primitive& primitive, const std::vector<Vector3f>& points,
                 const std::vector<Vector3f>& vertex_normals) {
    // Drop repeated corners (a hip roof on a square has no ridge).
    std::vector<Vector3f> corners;
    std::vector<Vector3f> corner_normals;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!corners.empty() && (points[i] - corners.back()).norm() < 1e-6f) continue;
        corners.push_back(points[i]);
        if (!vertex_normals.empty()) corner_normals.push_back(vertex_normals[i]);
    }
    while (corners.size() > 1 && (corners.front() - corners.back()).norm() < 1e-6f) {
        corners.pop_back();
        if (!corner_normals.empty()) corner_normals.pop_back();
    }
    if (corners.size() < 3) return;
    // Newell's method: the area-weighted normal of a planar polygon.
    Vector3f area = Vector3f::Zero();
    for (std::size_t i = 0; i < corners.size(); ++i)
        area += corners[i].cross(corners[(i + 1) % corners.size()]);
    if (area.norm() < 1e-9f) return;
    Vector3f normal = area.normalized();
    Vector3f tangent = (corners[1] - corners[0]).normalized();
    auto first = std::uint32_t(primitive.positions.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
        primitive.positions.push_back(corners[i]);
        primitive.normals.push_back(corner_normals.empty() ? normal : corner_normals[i]);
        primitive.tangents.emplace_back(tangent.x(), tangent.y(), tangent.z(), 1.0f);
    }
    for (std::uint32_t i = 1; i + 1 < corners.size(); ++i) {
        primitive.indices.push_back(first);
        primitive.indices.push_back(first + i);
        primitive.indices.push_back(first + i + 1);
    }
    primitive.polygon_count += 1;
}

Primitive builtin_primitive(const std::string& name, const Vector3f& size, int segments) {
    Primitive primitive;
    if (name == "box") {
        for (const ScopeFace& face : scope_faces(size))
            add_rectangle(primitive, face.origin, face.u * face.width, face.v * face.height);
    } else if (name == "quad") {
        add_rectangle(primitive, Vector3f(0, 0, size.z()), Vector3f(size.x(), 0, 0),
                      Vector3f(0, size.y(), 0));
    } else if (name == "cylinder") {
        add_cylinder(primitive, size, std::max(3, segments));
    } else if (name == "gable") {
        add_gable(primitive, size);
    } else {
        add_hip(primitive, size);
    }
    return primitive;
}

void place_in_world(Primitive& primitive, const ScopeBox& scope) {
    for (Vector3f& position : primitive.positions) position = scope.to_world(position);
    for (Vector3f& normal : primitive.normals) normal = scope.axes * normal;
    for (Eigen::Vector4f& tangent : primitive.tangents) tangent.head<3>() = scope.axes * tangent.head<3>();
}

void planar_texture_coordinates(Primitive& primitive, float tile_metres) {
    primitive.uvs.resize(primitive.positions.size());
    for (std::size_t i = 0; i < primitive.positions.size(); ++i) {
        Vector3f tangent = primitive.tangents[i].head<3>();
        Vector3f bitangent = primitive.normals[i].cross(tangent);
        primitive.uvs[i] =
            Eigen::Vector2f(primitive.positions[i].dot(tangent), -primitive.positions[i].dot(bitangent)) /
            tile_metres;
    }
}

}  // namespace boxlod
