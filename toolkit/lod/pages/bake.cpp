#include "toolkit/lod/pages/bake.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace boxlod {

std::array<OrientedBoxFace, 6> oriented_box_faces(const OrientedBox& box) {
    std::array<OrientedBoxFace, 6> faces;
    for (int k = 0; k < 3; ++k)
        for (int s = 0; s < 2; ++s) {
            OrientedBoxFace& face = faces[k * 2 + s];
            float sign = s == 0 ? 1.0f : -1.0f;
            face.normal = box.axes.col(k) * sign;
            face.center = box.center + face.normal * box.half_extents[k];
            face.half_depth = box.half_extents[k];
            int a = (k + 1) % 3, b = (k + 2) % 3;
            // Upright: the in-plane axis most aligned with +Y; horizontal faces use -Z.
            Eigen::Vector3f reference = Eigen::Vector3f::UnitY();
            if (std::abs(box.axes.col(a).y()) < 0.5f && std::abs(box.axes.col(b).y()) < 0.5f)
                reference = -Eigen::Vector3f::UnitZ();
            int up =
                std::abs(box.axes.col(b).dot(reference)) > std::abs(box.axes.col(a).dot(reference)) ? b : a;
            int side = up == a ? b : a;
            face.bitangent = box.axes.col(up);
            if (face.bitangent.dot(reference) < 0) face.bitangent = -face.bitangent;
            face.tangent = face.bitangent.cross(face.normal);
            face.half_height = box.half_extents[up];
            face.half_width = box.half_extents[side];
        }
    return faces;
}

void dilate_colors(Image8& color) {
    const int w = color.width, h = color.height;
    std::vector<int> ring(std::size_t(w) * h, -1);  // -1 unassigned, 0 covered, r filled in ring r
    std::vector<int> frontier;
    for (int i = 0; i < w * h; ++i)
        if (color.pixels[std::size_t(i) * 4 + 3] > 0) ring[i] = 0;
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int r = 1;; ++r) {
        frontier.clear();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                if (ring[y * w + x] != -1) continue;
                for (int d = 0; d < 4; ++d) {
                    int nx = x + dx[d], ny = y + dy[d];
                    if (nx >= 0 && ny >= 0 && nx < w && ny < h && ring[ny * w + nx] >= 0 &&
                        ring[ny * w + nx] < r) {
                        frontier.push_back(y * w + x);
                        break;
                    }
                }
            }
        if (frontier.empty()) return;
        for (int i : frontier) {
            int x = i % w, y = i / w, sum[3] = {0, 0, 0}, count = 0;
            for (int d = 0; d < 4; ++d) {
                int nx = x + dx[d], ny = y + dy[d];
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                int j = ny * w + nx;
                if (ring[j] < 0 || ring[j] >= r) continue;
                for (int c = 0; c < 3; ++c) sum[c] += color.pixels[std::size_t(j) * 4 + c];
                ++count;
            }
            for (int c = 0; c < 3; ++c)
                color.pixels[std::size_t(i) * 4 + c] = std::uint8_t((sum[c] + count / 2) / count);
        }
        for (int i : frontier) ring[i] = r;
    }
}

namespace {

// The smallest rectangle holding every covered texel (alpha > 0); empty where none is.
TexelRect covered_rect(const Image8& color) {
    int x0 = color.width, y0 = color.height, x1 = 0, y1 = 0;
    for (int y = 0; y < color.height; ++y)
        for (int x = 0; x < color.width; ++x)
            if (color.at(x, y)[3]) {
                x0 = std::min(x0, x);
                y0 = std::min(y0, y);
                x1 = std::max(x1, x + 1);
                y1 = std::max(y1, y + 1);
            }
    return x1 > x0 ? TexelRect{x0, y0, x1 - x0, y1 - y0} : TexelRect{};
}

}  // namespace

BakedFace bake_face(const Drawable& subtree, const OrientedBoxFace& face, const Eigen::Vector2i& texels,
                    int threads) {
    // Near and far lie a hair outside the box so geometry flush with a face is kept.
    float depth = 2 * face.half_depth;
    float margin = std::max(depth, std::max(face.half_width, face.half_height)) * 1e-3f + 1e-6f;
    float back_off = depth + 4 * margin;  // the camera sits outside the face
    RenderSettings settings;
    settings.mode = RenderMode::albedo;
    settings.threads = threads;
    settings.camera = orthographic_camera(face.center + face.normal * back_off, face.center, face.bitangent,
                                          {face.half_width, face.half_height}, back_off - margin,
                                          back_off + depth + margin);
    const Camera& camera = settings.camera;
    Frame frame = make_frame(texels.x(), texels.y(), {0, 0, 0});
    render(subtree.batches, settings, frame);

    BakedFace baked;
    baked.color = Image8(texels.x(), texels.y(), 4, 0);
    baked.normal = Image8(texels.x(), texels.y(), 3, 0);
    baked.height = Image16(texels.x(), texels.y(), 1, 0);
    float n = camera.near_plane, f = camera.far_plane;
    for (std::size_t i = 0; i < frame.color.size(); ++i) {
        std::uint8_t* normal = &baked.normal.pixels[i * 3];
        // A texel is covered where the model is at least half opaque (the faces'
        // MASK cut-off); glass over nothing stays see-through. The frame holds
        // colour composited over black: divide by coverage to get the albedo.
        float coverage = frame.color[i].w();
        if (coverage < 0.5f) {
            normal[0] = 128;  // (0, 0, 1)
            normal[1] = 128;
            normal[2] = 255;
            continue;
        }
        for (int c = 0; c < 3; ++c)
            baked.color.pixels[i * 4 + c] = linear_to_srgb(frame.color[i][c] / coverage);
        baked.color.pixels[i * 4 + 3] = 255;
        const Eigen::Vector3f& w = frame.normal[i];
        Eigen::Vector3f t(w.dot(face.tangent), w.dot(face.bitangent), w.dot(face.normal));
        for (int c = 0; c < 3; ++c)
            normal[c] = std::uint8_t(std::lround(std::clamp(t[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255));
        // Orthographic window depth is linear from near to far; the face plane lies at back_off.
        float distance = n + frame.depth[i] * (f - n) - back_off;
        float height = depth > 0 ? 1 - distance / depth : 1;
        baked.height.pixels[i] = std::uint16_t(std::lround(std::clamp(height, 0.0f, 1.0f) * 65535));
    }
    dilate_colors(baked.color);
    baked.covered = covered_rect(baked.color);
    return baked;
}

}  // namespace boxlod
