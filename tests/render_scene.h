// A small scene for renderer tests: a textured floor (checker colour, bump
// normal map, height map) and an untextured box, built in code.
#pragma once
#include "renderer/renderer.h"

#include <cmath>
#include <memory>

namespace boxlod::test {

struct RenderScene {
    Mesh floor, box;
    MipTexture color, normal, height;
    std::vector<Batch> batches;
    RenderSettings settings;
};

inline std::unique_ptr<RenderScene> make_render_scene() {
    auto scene = std::make_unique<RenderScene>();
    const int n = 64;
    Image8 color(n, n, 4, 255), normal(n, n, 4, 255), height(n, n, 4, 255);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            std::uint8_t* c = color.at(x, y);
            bool dark = ((x / 8) + (y / 8)) % 2;
            c[0] = dark ? 60 : 220;
            c[1] = dark ? 90 : 200;
            c[2] = dark ? 160 : 120;
            // Hemispherical bumps, one per 16x16 cell: height and its exact normal.
            float u = float(x % 16) - 7.5f, v = float(y % 16) - 7.5f, r2 = (u * u + v * v) / 49.0f;
            float h = r2 < 1 ? std::sqrt(1 - r2) : 0;
            float dx = r2 < 1 && h > 0.05f ? u / 49.0f / h : 0, dy = r2 < 1 && h > 0.05f ? v / 49.0f / h : 0;
            float len = std::sqrt(dx * dx + dy * dy + 1);
            std::uint8_t* m = normal.at(x, y);
            m[0] = std::uint8_t(std::lround((dx / len * 0.5f + 0.5f) * 255));
            m[1] = std::uint8_t(std::lround((-dy / len * 0.5f + 0.5f) * 255));  // green points up the image
            m[2] = std::uint8_t(std::lround((1 / len * 0.5f + 0.5f) * 255));
            std::uint8_t* e = height.at(x, y);
            e[0] = e[1] = e[2] = std::uint8_t(std::lround((0.5f + 0.5f * h) * 255));
        }
    scene->color = make_texture(color, ColorSpace::srgb);
    scene->normal = make_texture(normal, ColorSpace::linear);
    scene->height = make_texture(height, ColorSpace::linear);

    Mesh& floor = scene->floor;
    floor.positions = {{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}};
    floor.normals.assign(4, Eigen::Vector3f(0, 1, 0));
    floor.uvs = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    floor.indices = {0, 2, 1, 0, 3, 2};

    Mesh& box = scene->box;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            Eigen::Vector3f n = Eigen::Vector3f::Unit(axis) * side;
            Eigen::Vector3f u = Eigen::Vector3f::Unit((axis + 1) % 3),
                            v = Eigen::Vector3f::Unit((axis + 2) % 3);
            if (side < 0) std::swap(u, v);
            auto base = std::uint32_t(box.positions.size());
            Eigen::Vector3f centre(0, 0.5f, 0);
            for (auto [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                box.positions.push_back(centre + (n + u * float(a) + v * float(b)) * 0.5f);
                box.normals.push_back(n);
            }
            box.indices.insert(box.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }

    Batch floor_batch;
    floor_batch.mesh = &scene->floor;
    floor_batch.surface.color = &scene->color;
    floor_batch.surface.normal = &scene->normal;
    floor_batch.surface.height = &scene->height;
    Batch box_batch;
    box_batch.mesh = &scene->box;
    box_batch.surface.base_color = {0.8f, 0.3f, 0.2f, 1};
    box_batch.surface.shininess = 16;
    scene->batches = {floor_batch, box_batch};

    scene->settings.camera = camera_at_position({1, 1, 1}, {0, 0.3f, 0}, 4.5f, 45, 3);
    scene->settings.light.position = {3, 5, 2};
    scene->settings.parallax_scale = 0.08f;
    scene->settings.parallax_bias = -0.04f;
    return scene;
}

}  // namespace boxlod::test
