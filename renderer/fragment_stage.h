// The renderer's fragment stage, internal to renderer/ (renderer.cpp is its
// one reader): a tile's visibility buffer of triangle ids becomes Fragments,
// one pixel or lane_count pixels at a time, handed to the Shader
// (renderer/shading.h). Here too is what the pipeline's stages share about a
// frame in flight: its screen triangles, binned to tiles in chunks.
#pragma once
#include "renderer/rasterizer.h"
#include "renderer/scene.h"
#include "renderer/shading.h"

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace boxlod::pipeline {

constexpr int tile_bits = 6, tile_size = 1 << tile_bits;
constexpr int chunk_index_bits = 19;  // a chunk of 2^15 triangles clips into at most 7 * 2^15 < 2^19 pieces

// Columns x0..x1 and rows y0..y1 of tiles, inclusive.
struct TileRange {
    int x0, y0, x1, y1;
};

// Screen triangles of one chunk of the input, binned to tiles (CSR layout).
struct Chunk {
    std::vector<ScreenTriangle> triangles;
    std::vector<ClippedWeights> weights;
    std::vector<std::uint32_t> bin_start;    // per tile, into bin_items; size tiles + 1
    std::vector<std::uint32_t> bin_items;    // triangle indices within this chunk, in submission order
    std::vector<TileRange> tiles_of;         // scratch while binning: the tiles of each triangle
    std::vector<std::uint32_t> tile_counts;  // and the triangles of each tile
};

// A frame in flight, as its tiles are shaded.
struct Context {
    const std::vector<Batch>& batches;
    const RenderSettings& settings;
    const std::vector<Chunk>& chunks;
    std::size_t chunk_count;  // chunks in use this frame (the scratch may hold more)
    const Shader& shader;
    bool translated = false;  // some batch has a translation: else fragments skip it
};

inline const ScreenTriangle& triangle_of(const Context& c, std::uint32_t id,
                                         const std::vector<ClippedWeights>*& weights) {
    const Chunk& chunk = c.chunks[id >> chunk_index_bits];
    weights = &chunk.weights;
    return chunk.triangles[id & ((1u << chunk_index_bits) - 1)];
}

template <typename T>
T interpolate(const std::vector<T>& values, const std::uint32_t* v, const Eigen::Vector3f& b) {
    return values[v[0]] * b[0] + values[v[1]] * b[1] + values[v[2]] * b[2];
}

// What shading reads of one visible triangle, gathered once for all of its
// pixels (a tile is shaded row by row, and neighbours mostly share a
// triangle); every value is computed as it would be per pixel.
struct TriangleSetup {
    const ScreenTriangle* screen;
    const Batch* batch;
    const std::uint32_t* v;  // the source triangle's vertex indices
    BarycentricSetup barycentrics;
    Eigen::Vector3f geometric_normal;
    // The tangent frame from the uv gradient (Lengyel 2001), for meshes with uvs
    // but no tangents, before it is made orthogonal to each pixel's normal.
    bool has_uv_frame;
    Eigen::Vector3f uv_tangent, uv_bitangent;
    // The uv gradient, where the surface's height map states its depth.
    bool has_uv_gradient;
    UvGradient uv_gradient;
};

void set_up_triangle(const Context& c, std::uint32_t id, TriangleSetup& setup);

// One pixel of a triangle shaded, with the wireframe over it when asked.
ShadedPixel shade_pixel(const Context& c, const TriangleSetup& setup, int x, int y, bool reads_uv);

// A tile's shaded colours and normals, row stride tile_size.
struct ShadedTile {
    Eigen::Vector3f color[tile_size * tile_size], normal[tile_size * tile_size];
};

// Every visible pixel of the tile shaded: in lanes where the shader takes them.
void shade_tile(const Context& c, const TileTarget& tile, ShadedTile& out);

}  // namespace boxlod::pipeline
