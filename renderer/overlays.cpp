#include "renderer/overlays.h"

#include <Eigen/Geometry>
#include <cmath>

namespace boxlod {

void draw_line(Frame& frame, const Camera& camera, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
               const Eigen::Vector3f& color, int width) {
    Eigen::Matrix4f view_projection =
        projection_matrix(camera, float(frame.width) / float(frame.height)) * view_matrix(camera);
    Eigen::Vector4f p = view_projection * a.homogeneous(), q = view_projection * b.homogeneous();
    // Clip the segment at the near plane (z >= -w).
    float dp = p.z() + p.w(), dq = q.z() + q.w();
    if (dp < 0 && dq < 0) return;
    if (dp < 0) p = p + (q - p) * (dp / (dp - dq));
    if (dq < 0) q = q + (p - q) * (dq / (dq - dp));
    auto window = [&](const Eigen::Vector4f& c) {
        return Eigen::Vector2f((c.x() / c.w() + 1) * 0.5f * float(frame.width),
                               (1 - c.y() / c.w()) * 0.5f * float(frame.height));
    };
    Eigen::Vector2f s = window(p), e = window(q);
    float length = (e - s).norm();
    if (!std::isfinite(length)) return;
    int steps = std::max(1, int(std::ceil(std::min(length, 1e5f))));
    for (int i = 0; i <= steps; ++i) {
        Eigen::Vector2f point = s + (e - s) * (float(i) / float(steps));
        int cx = int(std::floor(point.x())), cy = int(std::floor(point.y()));
        for (int dy = -(width - 1) / 2; dy <= width / 2; ++dy)
            for (int dx = -(width - 1) / 2; dx <= width / 2; ++dx) {
                int x = cx + dx, y = cy + dy;
                if (x < 0 || y < 0 || x >= frame.width || y >= frame.height) continue;
                frame.color[std::size_t(y) * frame.width + x] =
                    Eigen::Vector4f(color.x(), color.y(), color.z(), 1);
            }
    }
}

void draw_axes(Frame& frame, const Camera& camera, const Eigen::Vector3f& origin, float length) {
    for (int axis = 0; axis < 3; ++axis)
        draw_line(frame, camera, origin, origin + Eigen::Vector3f::Unit(axis) * length,
                  Eigen::Vector3f::Unit(axis), 2);
}

void draw_divider(Frame& frame, int x, const Eigen::Vector3f& color) {
    if (x < 0 || x >= frame.width) return;
    for (int y = 0; y < frame.height; ++y)
        frame.color[std::size_t(y) * frame.width + x] = Eigen::Vector4f(color.x(), color.y(), color.z(), 1);
}

}  // namespace boxlod
