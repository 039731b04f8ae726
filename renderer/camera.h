// Cameras (docs/design.md: Rendering): right-handed, Y up, looking down -Z in view
// space; OpenGL clip space (NDC z in [-1, 1]).
#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace boxlod {

struct Camera {
    Eigen::Vector3f position{0, 0, 5};
    Eigen::Vector3f target{0, 0, 0};
    Eigen::Vector3f up{0, 1, 0};
    bool orthographic = false;
    float fovy_degrees = 45;                           // perspective: vertical field of view
    float left = -1, right = 1, bottom = -1, top = 1;  // orthographic: window in view space
    float near_plane = 0.1f, far_plane = 100;
};

// What makes a camera unusable (eye on the target, no up direction, up along
// the view, field of view outside (0, 180)), or "" for a usable one.
std::string camera_problem(const Camera& camera);

Eigen::Matrix4f view_matrix(const Camera& camera);
// `aspect` = width / height; ignored for orthographic cameras, whose window is explicit.
Eigen::Matrix4f projection_matrix(const Camera& camera, float aspect);

// False only when the sphere lies wholly outside one plane of the view volume
// (planes from the rows of projection x view: Gribb and Hartmann, "Fast
// Extraction of Viewing Frustum Planes from the World-View-Projection
// Matrix", 2001), with a margin, so a sphere judged outside holds nothing the
// renderer would draw.
bool sphere_in_view(const Camera& camera, float aspect, const Eigen::Vector3f& center, float radius);

// The manual's 26 camera positions: the directions in {-1,0,1}^3 other than 0,
// named like "+X", "-Y", "+X+Y+Z".
std::vector<std::string> camera_position_names();
std::optional<Eigen::Vector3f> camera_direction(const std::string& name);

// Near and far fitted to a sphere of `radius` whose centre is `distance` from
// the camera: near as far out as the sphere allows (depth precision), never
// behind the camera nor at 0 inside the sphere; far past the sphere. Every
// camera that frames a model or a city fits its depth range this way.
void fit_depth_range(Camera& camera, float distance, float radius);

// Camera at center + normalize(direction) * distance looking at center, up = +Y
// (-Z for straight down +Y, +Z for -Y); near/far fitted to a bounding sphere.
Camera camera_at_position(const Eigen::Vector3f& direction, const Eigen::Vector3f& center, float distance,
                          float fovy_degrees, float scene_radius);

// An orthographic camera at `eye` looking at `target`, `up` upright in the picture: a window of
// 2 half_window.x() x 2 half_window.y() metres about the view axis, depths from near_plane to
// far_plane metres in front of the eye. Baking, measuring and surface deviation view this way.
Camera orthographic_camera(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                           const Eigen::Vector3f& up, const Eigen::Vector2f& half_window, float near_plane,
                           float far_plane);

// Distance at which a sphere of `radius` fills the vertical field of view (with a margin).
float framing_distance(float radius, float fovy_degrees);

}  // namespace boxlod
