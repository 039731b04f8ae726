#include "experiments/sweep/impostor.h"

#include "base/parallel.h"
#include "toolkit/drawing/drawable.h"
#include "toolkit/model/framing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boxlod {
namespace {

constexpr int margin =
    2;  // texels of each cell outside the sphere's square, so mip levels 0-1 stay inside a cell

// The capture frame of a direction: bitangent up the image (world +Y projected,
// -Z looking straight down), tangent x bitangent = normal, as box faces bake.
OrientedBoxFace frame_of(const Eigen::Vector3f& direction, const Eigen::Vector3f& center, float half) {
    OrientedBoxFace f;
    f.normal = direction;
    Eigen::Vector3f up =
        std::abs(direction.y()) > 0.999f ? Eigen::Vector3f(0, 0, -1) : Eigen::Vector3f(0, 1, 0);
    f.bitangent = (up - direction * up.dot(direction)).normalized();
    f.tangent = f.bitangent.cross(f.normal);
    f.center = center;
    f.half_width = f.half_height = half;
    return f;
}

}  // namespace

int impostor_cell(const Bounds& bounds, double texel_size) {
    double diameter = 2 * double(framing_of(bounds).radius);  // the bounding sphere (model/framing.h)
    double texels = std::ceil(std::min(diameter / texel_size, 4096.0)) + 2 * margin;
    return int(std::clamp(texels, 8.0, 2048.0));
}

Eigen::Vector3f hemi_octahedral_direction(const Eigen::Vector2f& grid) {
    // Back from the turned square: the octahedron's upper half |x| + |z| <= 1.
    float x = (grid.x() + grid.y()) / 2, z = (grid.x() - grid.y()) / 2;
    float y = 1 - std::abs(x) - std::abs(z);
    return Eigen::Vector3f(x, y, z).normalized();
}

ImpostorAtlas make_impostor(const Model& model, int directions_per_side, int cell, int threads) {
    if (directions_per_side < 2 || directions_per_side > max_impostor_directions || cell < 8 || cell > 2048)
        throw std::invalid_argument(
            "make_impostor: directions per side in [2, 32] and cells of 8 to 2048 texels");
    const int k = directions_per_side;
    const Framing framing = model_framing(model);
    const Eigen::Vector3f center = framing.center;
    const float radius = framing.radius;
    const float half = radius * float(cell) / float(cell - 2 * margin);

    ImpostorAtlas atlas;
    atlas.directions_per_side = k;
    atlas.cell = cell;
    atlas.color = Image8(k * cell, k * cell, 4, 0);
    atlas.normal = Image8(k * cell, k * cell, 3, 0);
    for (int row = 0; row < k; ++row)
        for (int column = 0; column < k; ++column) {
            Eigen::Vector2f grid((float(column) + 0.5f) / float(k) * 2 - 1,
                                 (float(row) + 0.5f) / float(k) * 2 - 1);
            atlas.frames.push_back(frame_of(hemi_octahedral_direction(grid), center, half));
        }
    auto drawable = make_drawable_model(model, nullptr, threads);
    parallel_for(atlas.frames.size(), threads, [&](std::size_t i) {
        OrientedBoxFace capture =
            atlas.frames[i];  // the window on the sphere's near side, depth its diameter
        capture.center = center + capture.normal * radius;
        capture.half_depth = radius;
        BakedFace baked = bake_face(drawable->drawable, capture, {cell, cell}, 1);
        const int x0 = int(i) % k * cell, y0 = int(i) / k * cell;
        for (int y = 0; y < cell; ++y) {
            std::copy_n(baked.color.at(0, y), 4 * cell, atlas.color.at(x0, y0 + y));
            std::copy_n(baked.normal.at(0, y), 3 * cell, atlas.normal.at(x0, y0 + y));
        }
    });
    return atlas;
}

int nearest_direction(const ImpostorAtlas& atlas, const Eigen::Vector3f& eye) {
    if (atlas.frames.empty()) return 0;
    Eigen::Vector3f toward = eye - atlas.frames[0].center;
    int best = 0;
    for (int i = 1; i < int(atlas.frames.size()); ++i)
        if (atlas.frames[std::size_t(i)].normal.dot(toward) >
            atlas.frames[std::size_t(best)].normal.dot(toward))
            best = i;
    return best;
}

Model impostor_model(const ImpostorAtlas& atlas, const Eigen::Vector3f& eye, const std::string& source) {
    Model model;
    model.source = source;
    model.textures.push_back({"impostor_color.png", atlas.color, {}, Wrap::clamp});
    model.textures.push_back({"impostor_normal.png", atlas.normal, {}, Wrap::clamp});
    Material material;
    material.name = "impostor";
    material.base_color_texture = 0;
    material.normal_texture = 1;
    material.alpha_mode = AlphaMode::mask;
    model.materials.push_back(material);
    add_node(model, -1, "impostor");
    Primitive& quad = model.nodes[0].primitives.emplace_back();
    quad.material = 0;

    const int i = nearest_direction(atlas, eye), k = atlas.directions_per_side;
    const OrientedBoxFace& f = atlas.frames[std::size_t(i)];
    const float side = float(k * atlas.cell), u0 = float(i % k * atlas.cell) / side,
                v0 = float(i / k * atlas.cell) / side;
    const float u1 = u0 + float(atlas.cell) / side, v1 = v0 + float(atlas.cell) / side;
    // TL, BL, BR, TR seen from the viewer, as a baked box face's quad (toolkit/lod/lod_builder.cpp).
    const Eigen::Vector3f t = f.tangent * f.half_width, b = f.bitangent * f.half_height;
    const Eigen::Vector3f corners[4] = {f.center - t + b, f.center - t - b, f.center + t - b,
                                        f.center + t + b};
    const Eigen::Vector2f uvs[4] = {{u0, v0}, {u0, v1}, {u1, v1}, {u1, v0}};
    for (int c = 0; c < 4; ++c) {
        quad.positions.push_back(corners[c]);
        quad.normals.push_back(f.normal);
        quad.uvs.push_back(uvs[c]);
        quad.tangents.emplace_back(f.tangent.x(), f.tangent.y(), f.tangent.z(), 1.0f);
    }
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.polygon_count = 1;
    return model;
}

}  // namespace boxlod
