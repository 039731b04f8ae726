#include "renderer/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace boxlod {

std::string camera_problem(const Camera& camera) {
    if (!camera.position.allFinite() || !camera.target.allFinite() || !camera.up.allFinite())
        return "the camera is not finite";
    Eigen::Vector3f forward = camera.target - camera.position;
    if (!(forward.norm() > 1e-6f * std::max(1.0f, camera.position.norm())))
        return "the camera's position equals its target";
    if (!(camera.up.norm() > 0)) return "the camera's up direction is zero";
    if (!(forward.normalized().cross(camera.up.normalized()).norm() > 1e-4f))
        return "the camera's up direction is along its view";
    if (!camera.orthographic && !(camera.fovy_degrees > 0 && camera.fovy_degrees < 180))
        return "the camera's field of view must be in (0, 180) degrees";
    return "";
}

Eigen::Matrix4f view_matrix(const Camera& camera) {
    Eigen::Vector3f forward = (camera.target - camera.position).normalized();
    Eigen::Vector3f side = forward.cross(camera.up).normalized();
    Eigen::Vector3f up = side.cross(forward);
    Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
    view.block<1, 3>(0, 0) = side.transpose();
    view.block<1, 3>(1, 0) = up.transpose();
    view.block<1, 3>(2, 0) = -forward.transpose();
    view(0, 3) = -side.dot(camera.position);
    view(1, 3) = -up.dot(camera.position);
    view(2, 3) = forward.dot(camera.position);
    return view;
}

Eigen::Matrix4f projection_matrix(const Camera& camera, float aspect) {
    float n = camera.near_plane, f = camera.far_plane;
    Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
    if (camera.orthographic) {  // glOrtho
        float l = camera.left, r = camera.right, b = camera.bottom, t = camera.top;
        p(0, 0) = 2 / (r - l);
        p(1, 1) = 2 / (t - b);
        p(2, 2) = -2 / (f - n);
        p(0, 3) = -(r + l) / (r - l);
        p(1, 3) = -(t + b) / (t - b);
        p(2, 3) = -(f + n) / (f - n);
        p(3, 3) = 1;
    } else {  // gluPerspective
        float cot = 1 / std::tan(camera.fovy_degrees * float(M_PI) / 360);
        p(0, 0) = cot / aspect;
        p(1, 1) = cot;
        p(2, 2) = (f + n) / (n - f);
        p(2, 3) = 2 * f * n / (n - f);
        p(3, 2) = -1;
    }
    return p;
}

bool sphere_in_view(const Camera& camera, float aspect, const Eigen::Vector3f& center, float radius) {
    const Eigen::Matrix4d m = (projection_matrix(camera, aspect) * view_matrix(camera)).cast<double>();
    const Eigen::Vector4d point(center.x(), center.y(), center.z(), 1);
    const double margin = 1e-3 * (1 + double(radius));  // forgives the renderer's float rounding
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {  // w >= -x, w >= x, ... (clip space, z in [-w, w])
            const Eigen::Vector4d plane = m.row(3) + side * m.row(axis);
            const double length = plane.head<3>().norm();
            if (length > 0 && plane.dot(point) / length < -(double(radius) + margin)) return false;
        }
    return true;
}

std::vector<std::string> camera_position_names() {
    std::vector<std::string> names;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                if (!x && !y && !z) continue;
                std::string name;
                int d[3] = {x, y, z};
                const char* axes = "XYZ";
                for (int i = 0; i < 3; ++i)
                    if (d[i]) name += std::string(d[i] > 0 ? "+" : "-") + axes[i];
                names.push_back(name);
            }
    return names;
}

std::optional<Eigen::Vector3f> camera_direction(const std::string& name) {
    Eigen::Vector3f direction = Eigen::Vector3f::Zero();
    bool seen[3] = {false, false, false};
    for (std::size_t i = 0; i < name.size(); i += 2) {
        if (i + 1 >= name.size() || (name[i] != '+' && name[i] != '-')) return std::nullopt;
        char axis = char(std::toupper(static_cast<unsigned char>(name[i + 1])));
        if (axis < 'X' || axis > 'Z' || seen[axis - 'X']) return std::nullopt;
        seen[axis - 'X'] = true;
        direction[axis - 'X'] = name[i] == '+' ? 1.0f : -1.0f;
    }
    if (direction.isZero()) return std::nullopt;
    return direction;
}

Camera camera_at_position(const Eigen::Vector3f& direction, const Eigen::Vector3f& center, float distance,
                          float fovy_degrees, float scene_radius) {
    Camera camera;
    Eigen::Vector3f d = direction.normalized();
    camera.position = center + d * distance;
    camera.target = center;
    camera.fovy_degrees = fovy_degrees;
    if (d.x() == 0 && d.z() == 0)
        camera.up = d.y() > 0 ? Eigen::Vector3f(0, 0, -1) : Eigen::Vector3f(0, 0, 1);
    fit_depth_range(camera, distance, scene_radius);
    return camera;
}

void fit_depth_range(Camera& camera, float distance, float radius) {
    camera.near_plane = std::max(distance - radius, std::max(distance * 1e-3f, radius * 1e-4f));
    camera.far_plane = distance + radius;
    if (camera.far_plane <= camera.near_plane * 1.001f) camera.far_plane = camera.near_plane * 2;
}

Camera orthographic_camera(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                           const Eigen::Vector3f& up, const Eigen::Vector2f& half_window, float near_plane,
                           float far_plane) {
    Camera camera;
    camera.orthographic = true;
    camera.position = eye;
    camera.target = target;
    camera.up = up;
    camera.left = -half_window.x();
    camera.right = half_window.x();
    camera.bottom = -half_window.y();
    camera.top = half_window.y();
    camera.near_plane = near_plane;
    camera.far_plane = far_plane;
    return camera;
}

float framing_distance(float radius, float fovy_degrees) {
    return 1.1f * radius / std::sin(fovy_degrees * float(M_PI) / 360);
}

}  // namespace boxlod
