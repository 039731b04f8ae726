// The rasterizer benchmark's scene: a wavy height-field grid of about a
// million small triangles filling a 1920x1080 view, lit per pixel.
#pragma once
#include "renderer/renderer.h"

#include <cmath>

namespace boxlod::bench {

constexpr int frame_width = 1920, frame_height = 1080;

// (cells + 1)^2 vertices, 2 * cells^2 triangles; 708 cells give 1,002,528 triangles.
inline Mesh height_field(int cells) {
    Mesh mesh;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            float x = float(i) / float(cells) * 2 - 1, z = float(j) / float(cells) * 2 - 1;
            float y = 0.05f * std::sin(x * 12) * std::cos(z * 9);
            Eigen::Vector3f n(-0.05f * 12 * std::cos(x * 12) * std::cos(z * 9), 1,
                              0.05f * 9 * std::sin(x * 12) * std::sin(z * 9));
            mesh.positions.emplace_back(x * 1.6f, y, z);
            mesh.normals.push_back(n.normalized());
        }
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            std::uint32_t a = std::uint32_t(j * (cells + 1) + i), b = a + 1, c = a + std::uint32_t(cells) + 1,
                          d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

inline RenderSettings benchmark_settings(int threads) {
    RenderSettings settings;
    settings.mode = RenderMode::untextured;
    settings.camera.position = {0, 2.2f, 0.01f};
    settings.camera.target = {0, 0, 0};
    settings.camera.fovy_degrees = 45;
    settings.camera.near_plane = 1;
    settings.camera.far_plane = 4;
    settings.light.position = {1, 3, 1};
    settings.threads = threads;
    return settings;
}

}  // namespace boxlod::bench
