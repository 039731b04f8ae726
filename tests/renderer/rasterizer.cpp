#include "renderer/rasterizer.h"

#include "renderer/camera.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include "base/random.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

using namespace boxlod;

namespace {

constexpr int size = 48;

ScreenTriangle screen_triangle(Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d c, float z) {
    ScreenTriangle t;
    Eigen::Vector2d v[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        t.x[i] = std::int32_t(std::lround(v[i].x() * 256));
        t.y[i] = std::int32_t(std::lround(v[i].y() * 256));
        t.z[i] = z;
        t.inv_w[i] = 1;
    }
    t.batch = t.triangle = 0;
    return t;
}

// How often each pixel was written: every triangle lies in front of the ones before.
std::vector<int> coverage_counts(const std::vector<ScreenTriangle>& triangles) {
    std::vector<float> depth(size * size, std::numeric_limits<float>::infinity());
    std::vector<std::uint32_t> ids(size * size, no_triangle);
    std::vector<int> counts(size * size, 0);
    TileTarget tile{0, 0, size, size, size, depth.data(), ids.data()};
    FragmentTest count = [&](const ScreenTriangle&, int x, int y) {
        ++counts[y * size + x];
        return true;
    };
    for (std::size_t i = 0; i < triangles.size(); ++i)
        rasterize_triangle(triangles[i], std::uint32_t(i), tile, &count);
    return counts;
}

}  // namespace

TEST(Rasterizer, FanOverRectangleTouchesEveryPixelExactlyOnce) {
    // Centre on a pixel centre; spokes to 64 points of the rectangle's boundary,
    // several of them through pixel centres (horizontal, vertical, diagonal).
    const double x0 = 3.25, y0 = 4.75, x1 = 41.75, y1 = 40.25;
    Eigen::Vector2d centre(20.5, 20.5);
    std::vector<Eigen::Vector2d> ring;
    for (int i = 0; i < 16; ++i) ring.emplace_back(x0 + (x1 - x0) * i / 16, y0);
    for (int i = 0; i < 16; ++i) ring.emplace_back(x1, y0 + (y1 - y0) * i / 16);
    for (int i = 0; i < 16; ++i) ring.emplace_back(x1 - (x1 - x0) * i / 16, y1);
    for (int i = 0; i < 16; ++i) ring.emplace_back(x0, y1 - (y1 - y0) * i / 16);
    ring.emplace_back(20.5, y0);  // the diagonal through pixel centres
    ring.emplace_back(x1, 20.5);
    ring.emplace_back(40.25, 40.25);
    std::sort(ring.begin(), ring.end(), [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return std::atan2(a.y() - centre.y(), a.x() - centre.x()) <
               std::atan2(b.y() - centre.y(), b.x() - centre.x());
    });
    std::vector<ScreenTriangle> fan;
    for (std::size_t i = 0; i < ring.size(); ++i)
        fan.push_back(screen_triangle(centre, ring[i], ring[(i + 1) % ring.size()], 1.0f - float(i) * 0.01f));
    std::vector<int> counts = coverage_counts(fan);
    int inside = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            bool expected = x + 0.5 > x0 && x + 0.5 < x1 && y + 0.5 > y0 && y + 0.5 < y1;
            ASSERT_EQ(counts[y * size + x], expected ? 1 : 0) << "pixel " << x << "," << y;
            inside += expected;
        }
    EXPECT_EQ(inside, 39 * 35);
}

TEST(Rasterizer, TopLeftRuleOwnsTopAndLeftEdgesOnly) {
    // A square with its edges exactly on pixel centres 2.5 .. 6.5.
    auto a = Eigen::Vector2d(2.5, 2.5), b = Eigen::Vector2d(6.5, 2.5), c = Eigen::Vector2d(6.5, 6.5),
         d = Eigen::Vector2d(2.5, 6.5);
    for (bool clockwise : {false, true}) {
        std::vector<ScreenTriangle> square =
            clockwise
                ? std::vector<ScreenTriangle>{screen_triangle(a, b, c, 0.5f), screen_triangle(a, c, d, 0.4f)}
                : std::vector<ScreenTriangle>{screen_triangle(a, c, b, 0.5f), screen_triangle(a, d, c, 0.4f)};
        std::vector<int> counts = coverage_counts(square);
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 10; ++x)
                EXPECT_EQ(counts[y * size + x], (x >= 2 && x < 6 && y >= 2 && y < 6) ? 1 : 0)
                    << x << "," << y;
    }
}

TEST(Rasterizer, GridOfTrianglesOnPixelCentresLeavesNoGapsOrOverlaps) {
    std::vector<ScreenTriangle> grid;
    float z = 1;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) {
            Eigen::Vector2d p(4.5 + i * 6.5, 3.5 + j * 7), q = p + Eigen::Vector2d(6.5, 0),
                                                           r = p + Eigen::Vector2d(6.5, 7),
                                                           s = p + Eigen::Vector2d(0, 7);
            grid.push_back(screen_triangle(p, q, r, z -= 0.001f));
            grid.push_back(screen_triangle(p, r, s, z -= 0.001f));
        }
    std::vector<int> counts = coverage_counts(grid);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            bool inside = x + 0.5 >= 4.5 && x + 0.5 < 4.5 + 39 && y + 0.5 >= 3.5 && y + 0.5 < 3.5 + 42;
            ASSERT_EQ(counts[y * size + x], inside ? 1 : 0) << x << "," << y;
        }
}

// Wide triangles have each row's run of pixels solved from the edge equations
// (the division carried from row to row); it must give exactly the pixels whose
// centres the top-left rule puts inside, here checked centre by centre for
// triangles of every orientation and width, the last 200 with corners far
// outside the tile (guard-band sizes: edge values near 2^58). Each pixel's
// depth must be the one from its exact edge values, summed in the walk's
// order (runs take four centres at once in doubles while that is exact).
// Every walk (small triangles in lanes, narrow ones centre by centre, wide
// ones by solved runs, in lanes or not) against the edge functions themselves.
TEST(Rasterizer, EveryWalkCoversThePixelsAndDepthsOfTheEdgeFunctions) {
    Pcg32 random(12345, 1);  // the same triangles on every machine
    auto next = [&](int range) { return int(random.next_uint() % std::uint32_t(range)); };
    for (int n = 0; n < 1100; ++n) {
        ScreenTriangle t;
        // From triangle 500 on, small ones: corners within 9 pixels of a point,
        // so their boxes are under and over the 8 pixels of the small walk.
        const int centre_x = n >= 500 ? next(size) * 256 : 0, centre_y = n >= 500 ? next(size) * 256 : 0;
        for (int i = 0; i < 3; ++i) {
            // Corners on a coarse grid too, so edges run through pixel centres.
            const bool on_centre = next(3) == 0;
            t.x[i] = on_centre ? next(size) * 256 + 128 : next(size * 256);
            t.y[i] = on_centre ? next(size) * 256 + 128 : next(size * 256);
            if (n >= 300 && n < 500 && next(2) == 0) {  // up to 2^28 subpixels away, either side
                t.x[i] = (next(1 << 20) - (1 << 19)) * 512 + next(512);
                t.y[i] = (next(1 << 20) - (1 << 19)) * 512 + next(512);
            }
            if (n >= 500) {
                t.x[i] = centre_x + (on_centre ? (next(19) - 9) * 256 + 128 : next(18 * 256) - 9 * 256);
                t.y[i] = centre_y + (on_centre ? (next(19) - 9) * 256 + 128 : next(18 * 256) - 9 * 256);
            }
            t.z[i] = float(next(1 << 20)) / 1048573.0f;  // every mantissa bit used
            t.inv_w[i] = 1;
        }
        const std::int64_t area = std::int64_t(t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) -
                                  std::int64_t(t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
        if (area == 0) continue;
        std::vector<int> counts = coverage_counts({t});
        std::vector<float> depth(size * size, std::numeric_limits<float>::infinity());
        std::vector<std::uint32_t> ids(size * size, no_triangle);
        rasterize_triangle(t, 0, {0, 0, size, size, size, depth.data(), ids.data()}, nullptr);
        // Tile by tile (each tile its own buffer, so reads past a row show under
        // ASan): the same pixels and depths, wherever tiles cut the triangle.
        constexpr int tile_size = 16;
        for (int tile_y = 0; tile_y < size; tile_y += tile_size)
            for (int tile_x = 0; tile_x < size; tile_x += tile_size) {
                std::vector<float> tile_depth(tile_size * tile_size, std::numeric_limits<float>::infinity());
                std::vector<std::uint32_t> tile_ids(tile_size * tile_size, no_triangle);
                rasterize_triangle(t, 0,
                                   {tile_x, tile_y, tile_x + tile_size, tile_y + tile_size, tile_size,
                                    tile_depth.data(), tile_ids.data()},
                                   nullptr);
                for (int y = 0; y < tile_size; ++y)
                    for (int x = 0; x < tile_size; ++x) {
                        const std::size_t in_tile = std::size_t(y * tile_size + x),
                                          in_frame = std::size_t((tile_y + y) * size + tile_x + x);
                        ASSERT_EQ(tile_ids[in_tile], ids[in_frame])
                            << "triangle " << n << ", pixel " << tile_x + x << "," << tile_y + y;
                        ASSERT_EQ(std::bit_cast<std::uint32_t>(tile_depth[in_tile]),
                                  std::bit_cast<std::uint32_t>(depth[in_frame]))
                            << "triangle " << n << ", pixel " << tile_x + x << "," << tile_y + y;
                    }
            }
        const int sign = area > 0 ? 1 : -1;
        const int order[3] = {0, sign > 0 ? 1 : 2,
                              sign > 0 ? 2 : 1};  // the walk's corners, oriented to positive area
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const std::int64_t px = x * 256 + 128, py = y * 256 + 128;
                bool inside = true;
                std::int64_t weight[3];  // the edge value opposite each corner
                for (int k = 0; k < 3; ++k) {
                    const int a = (k + 1) % 3, b = (k + 2) % 3;
                    // Oriented to positive area; inside is E >= 0 on top and left edges, E > 0 elsewhere.
                    const std::int64_t dx = sign * std::int64_t(t.x[b] - t.x[a]),
                                       dy = sign * std::int64_t(t.y[b] - t.y[a]);
                    const std::int64_t e = dx * (py - t.y[a]) - dy * (px - t.x[a]);
                    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
                    inside = inside && (top_left ? e >= 0 : e > 0);
                    weight[k] = e;
                }
                ASSERT_EQ(counts[std::size_t(y * size + x)], inside ? 1 : 0)
                    << "triangle " << n << ", pixel " << x << "," << y;
                if (!inside) continue;
                double z = 0;
                for (int k : order) z += double(weight[k]) * double(t.z[k]);
                const float expected = float(z * (1.0 / double(area * sign)));
                ASSERT_EQ(std::bit_cast<std::uint32_t>(depth[std::size_t(y * size + x)]),
                          std::bit_cast<std::uint32_t>(expected))
                    << "triangle " << n << ", pixel " << x << "," << y;
            }
    }
}

TEST(Rasterizer, DepthTestIsLess) {
    auto t = screen_triangle({0, 0}, {20, 0}, {0, 20}, 0.5f);
    std::vector<float> depth(size * size, std::numeric_limits<float>::infinity());
    std::vector<std::uint32_t> ids(size * size, no_triangle);
    TileTarget tile{0, 0, size, size, size, depth.data(), ids.data()};
    rasterize_triangle(t, 1, tile, nullptr);
    rasterize_triangle(t, 2, tile, nullptr);  // equal depth: not less, keeps the first
    EXPECT_EQ(ids[2 * size + 2], 1u);
    EXPECT_EQ(depth[2 * size + 2], 0.5f);
    auto nearer = screen_triangle({0, 0}, {20, 0}, {0, 20}, 0.25f);
    rasterize_triangle(nearer, 3, tile, nullptr);
    EXPECT_EQ(ids[2 * size + 2], 3u);
}

namespace {
Viewport viewport(int w, int h) {
    Viewport v;
    v.width = w;
    v.height = h;
    return v;
}
}  // namespace

TEST(Rasterizer, ClippingAtTheNearPlaneKeepsSourceWeights) {
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, -1};
    camera.near_plane = 1;
    camera.far_plane = 10;
    Eigen::Matrix4f m = projection_matrix(camera, 1) * view_matrix(camera);
    // One vertex behind the camera, two in front.
    Eigen::Vector3f world[3] = {{0, -1, 2}, {-1, -1, -5}, {1, -1, -5}};
    Eigen::Vector4f clip[3];
    for (int i = 0; i < 3; ++i) clip[i] = m * world[i].homogeneous();
    std::vector<ScreenTriangle> out;
    std::vector<ClippedWeights> weights;
    setup_triangle(clip, 0, 7, Culling::none, viewport(64, 64), out, weights);
    ASSERT_FALSE(out.empty());
    for (const ScreenTriangle& t : out) {
        ASSERT_GE(t.clipped, 0);
        EXPECT_EQ(t.triangle, 7u);
        for (int i = 0; i < 3; ++i) {
            EXPECT_GE(t.z[i], 0.0f);
            EXPECT_LE(t.z[i], 1.0f);
            const Eigen::Vector3f& w = weights[t.clipped].weights[i];
            EXPECT_NEAR(w.sum(), 1.0f, 1e-6f);
            // Reconstructed from the weights, the vertex lies on or in front of the near plane.
            Eigen::Vector3f p = world[0] * w[0] + world[1] * w[1] + world[2] * w[2];
            EXPECT_LE(p.z(), -1 + 1e-4f);
        }
    }
    // Entirely behind the camera: nothing.
    Eigen::Vector3f behind[3] = {{0, 0, 2}, {1, 0, 3}, {0, 1, 3}};
    for (int i = 0; i < 3; ++i) clip[i] = m * behind[i].homogeneous();
    out.clear();
    setup_triangle(clip, 0, 0, Culling::none, viewport(64, 64), out, weights);
    EXPECT_TRUE(out.empty());
}

TEST(Rasterizer, HugeTriangleIsClippedToTheGuardBandAndCoversTheScreenOnce) {
    Eigen::Vector4f clip[3] = {{-1000, -1000, 0, 1}, {3000, -1000, 0, 1}, {-1000, 3000, 0, 1}};
    std::vector<ScreenTriangle> out;
    std::vector<ClippedWeights> weights;
    setup_triangle(clip, 0, 0, Culling::none, viewport(size, size), out, weights);
    ASSERT_GT(out.size(), 1u);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i].z[0] = out[i].z[1] = out[i].z[2] = 1.0f - float(i) * 0.01f;
    std::vector<int> counts = coverage_counts(out);
    for (int c : counts) ASSERT_EQ(c, 1);
}

TEST(Rasterizer, BackFacesAreCulledOnRequest) {
    Eigen::Vector4f ccw[3] = {{-0.5f, -0.5f, 0, 1}, {0.5f, -0.5f, 0, 1}, {0, 0.5f, 0, 1}};
    Eigen::Vector4f cw[3] = {ccw[0], ccw[2], ccw[1]};
    std::vector<ScreenTriangle> out;
    std::vector<ClippedWeights> weights;
    setup_triangle(ccw, 0, 0, Culling::back, viewport(32, 32), out, weights);
    EXPECT_EQ(out.size(), 1u);
    setup_triangle(cw, 0, 0, Culling::back, viewport(32, 32), out, weights);
    EXPECT_EQ(out.size(), 1u);
    setup_triangle(cw, 0, 0, Culling::front, viewport(32, 32), out, weights);
    EXPECT_EQ(out.size(), 2u);
    setup_triangle(cw, 0, 0, Culling::none, viewport(32, 32), out, weights);
    EXPECT_EQ(out.size(), 3u);
}

TEST(Rasterizer, SettingUpAMeshRangeIsSettingUpEachTriangleInOrder) {
    // Triangles 1..4 of a mesh: in view, back-facing, crossing the far plane,
    // without area; triangle 0 lies outside the range.
    // Clip space is the positions moved back and squeezed along z (w stays 1).
    const std::vector<Eigen::Vector3f> positions = {
        {-0.5f, -0.5f, 1}, {0.5f, -0.5f, 1}, {0, 0.5f, 1}, {0.2f, 0.1f, 5}, {0, 0, 2}};
    Eigen::Matrix4f to_clip = Eigen::Matrix4f::Identity();
    to_clip(2, 2) = 0.5f, to_clip(2, 3) = -0.5f;
    const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 1, 2, 0, 2, 1, 0, 1, 3, 0, 0, 4};
    const Viewport view = viewport(32, 32);
    std::vector<Eigen::Vector4f> clip;
    std::vector<ProjectedVertex> projected;
    for (const Eigen::Vector3f& p : positions) {
        clip.push_back(clip_position(to_clip, p));
        projected.push_back(project_vertex(clip.back(), view));
    }
    EXPECT_EQ(clip[3], Eigen::Vector4f(0.2f, 0.1f, 2, 1));  // beyond the far plane
    std::vector<ScreenTriangle> range, each;
    std::vector<ClippedWeights> range_weights, each_weights;
    const ProjectedMesh mesh{indices.data(), projected.data(), positions.data(), &to_clip};
    setup_triangles(mesh, 1, 5, 3, Culling::back, view, range, range_weights);
    for (std::uint32_t t = 1; t < 5; ++t) {
        const Eigen::Vector4f corners[3] = {clip[indices[t * 3]], clip[indices[t * 3 + 1]],
                                            clip[indices[t * 3 + 2]]};
        setup_triangle(corners, 3, t, Culling::back, view, each, each_weights);
    }
    ASSERT_EQ(range.size(), each.size());
    ASSERT_GE(range.size(), 2u);  // triangle 1 and the pieces of triangle 3
    EXPECT_EQ(range.front().triangle, 1u);
    EXPECT_EQ(range.back().triangle, 3u);
    ASSERT_EQ(range_weights.size(), each_weights.size());
    for (std::size_t i = 0; i < range.size(); ++i) {
        EXPECT_EQ(std::memcmp(&range[i], &each[i], sizeof(ScreenTriangle)), 0) << "triangle " << i;
        EXPECT_EQ(range[i].batch, 3u);
    }
    for (std::size_t i = 0; i < range_weights.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(range_weights[i].weights[k], each_weights[i].weights[k]);
}

TEST(Rasterizer, InterpolationIsPerspectiveCorrect) {
    // A floor receding from the camera; at each pixel, the barycentrics must
    // match the ray-plane intersection computed in world space.
    Camera camera;
    camera.position = {0, 1, 0};
    camera.target = {0, 0.5f, -3};
    camera.near_plane = 0.1f;
    camera.far_plane = 50;
    const int w = 64, h = 48;
    Eigen::Matrix4f view = view_matrix(camera), projection = projection_matrix(camera, float(w) / h);
    Eigen::Vector3f world[3] = {{-4, 0, -1}, {4, 0, -1}, {0, 0, -20}};
    Eigen::Vector4f clip[3];
    for (int i = 0; i < 3; ++i) clip[i] = projection * view * world[i].homogeneous();
    std::vector<ScreenTriangle> out;
    std::vector<ClippedWeights> weights;
    setup_triangle(clip, 0, 0, Culling::none, viewport(w, h), out, weights);
    ASSERT_EQ(out.size(), 1u);
    Eigen::Matrix4f inverse = (projection * view).inverse();
    int checked = 0;
    for (int y = 0; y < h; y += 3)
        for (int x = 0; x < w; x += 3) {
            Eigen::Vector3d l = screen_barycentrics(out[0], x + 0.5, y + 0.5);
            if (l.minCoeff() < 0.02) continue;  // well inside only
            Eigen::Vector3f b = source_barycentrics(out[0], weights, x + 0.5, y + 0.5);
            // The ray through the pixel centre, intersected with the floor y = 0.
            float nx = (x + 0.5f) / w * 2 - 1, ny = 1 - (y + 0.5f) / h * 2;
            Eigen::Vector4f far = inverse * Eigen::Vector4f(nx, ny, 1, 1);
            Eigen::Vector3f direction = (far.head<3>() / far.w() - camera.position).normalized();
            Eigen::Vector3f hit = camera.position + direction * (-camera.position.y() / direction.y());
            Eigen::Vector3f from_b = world[0] * b[0] + world[1] * b[1] + world[2] * b[2];
            EXPECT_NEAR((hit - from_b).norm() / (hit - camera.position).norm(), 0, 2e-3) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 30);
}
