// The rasterizer (docs/design.md: Rendering): homogeneous clipping, fixed-point
// snapping with 8 sub-pixel bits, edge functions with the top-left fill rule,
// depth test LESS. It fills a visibility buffer (triangle id + depth per
// pixel); shading happens afterwards, once per visible pixel.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace boxlod {

constexpr int subpixel_bits = 8;
constexpr std::uint32_t no_triangle = 0xffffffffu;

// A triangle after clipping and snapping, ready to rasterize and to shade.
struct ScreenTriangle {
    std::int32_t x[3], y[3];        // snapped window coordinates, 8 fractional bits, y down
    float z[3];                     // window depth in [0, 1]
    float inv_w[3];                 // 1 / clip w, for perspective-correct interpolation
    std::uint32_t batch, triangle;  // the source triangle
    std::int32_t clipped = -1;  // index into ClippedWeights, -1 = not clipped (vertex i is source vertex i)
};

// For clipped triangles: each vertex as barycentric weights of its source triangle.
struct ClippedWeights {
    Eigen::Vector3f weights[3];
};

struct Viewport {
    int width = 0, height = 0;
    int scissor_x0 = 0, scissor_y0 = 0, scissor_x1 = 1 << 30,
        scissor_y1 = 1 << 30;  // pixels [x0, x1) x [y0, y1)
};

enum class Culling { none, back, front };

// A vertex after the vertex stage: the planes of the view volume its clip-space
// position lies outside of and (inside all of them) its snapped window
// position, so that triangles sharing it do not snap it again. The clip-space
// position itself is not kept: set-up needs it only for the few triangles it
// clips, and recomputes it (20 bytes a vertex to write and to read, not 48).
struct ProjectedVertex {
    int outcode = 0;  // bit per plane: near, far, then x and y against the guard band; NaN is outside
    std::int32_t x = 0, y = 0;  // snapped window coordinates, as in ScreenTriangle
    float z = 0, inv_w = 0;
};
ProjectedVertex project_vertex(const Eigen::Vector4f& clip, const Viewport& viewport);
// The clip-space position of an object-space one: the vertex stage's and the
// clipper's, the very same floats.
inline Eigen::Vector4f clip_position(const Eigen::Matrix4f& to_clip, const Eigen::Vector3f& position) {
    return to_clip.col(0) * position.x() + to_clip.col(1) * position.y() + to_clip.col(2) * position.z() +
           to_clip.col(3);
}

// A mesh as the vertex stage left it.
struct ProjectedMesh {
    const std::uint32_t* indices = nullptr;      // three per triangle
    const ProjectedVertex* vertices = nullptr;   // project_vertex of each clip_position
    const Eigen::Vector3f* positions = nullptr;  // in object space
    const Eigen::Matrix4f* to_clip = nullptr;
};

// Clips triangles [begin, end) of a mesh against the view volume (near and
// far exactly, x and y against a guard band) and appends the snapped pieces,
// in order. Triangles facing away are dropped when culled; the stored corners
// keep their order.
void setup_triangles(const ProjectedMesh& mesh, std::size_t begin, std::size_t end, std::uint32_t batch,
                     Culling culling, const Viewport& viewport, std::vector<ScreenTriangle>& out,
                     std::vector<ClippedWeights>& weights);
// The same for one triangle given in clip space, as triangle `triangle` of batch `batch`.
void setup_triangle(const Eigen::Vector4f clip[3], std::uint32_t batch, std::uint32_t triangle,
                    Culling culling, const Viewport& viewport, std::vector<ScreenTriangle>& out,
                    std::vector<ClippedWeights>& weights);

// What barycentrics read of a screen triangle, gathered once so that pixels
// of one triangle share it; evaluating from it gives the very same doubles.
struct BarycentricSetup {
    double x0, y0, x1, y1, x2, y2, area;  // window coordinates, doubled signed area
    float inv_w[3];
    const ClippedWeights* clipped = nullptr;  // set for clipped triangles
};
BarycentricSetup barycentric_setup(const ScreenTriangle& t, const std::vector<ClippedWeights>& weights);

// Screen-space barycentric coordinates (linear in x, y) at a window point.
Eigen::Vector3d screen_barycentrics(const BarycentricSetup& s, double px, double py);
Eigen::Vector3d screen_barycentrics(const ScreenTriangle& t, double px, double py);
// Perspective-correct barycentrics of the source triangle at a window point.
Eigen::Vector3f source_barycentrics(const BarycentricSetup& s, double px, double py);
Eigen::Vector3f source_barycentrics(const ScreenTriangle& t, const std::vector<ClippedWeights>& weights,
                                    double px, double py);
// Barycentrics of a clipped piece's corners as barycentrics of its source triangle.
inline Eigen::Vector3f source_of_clipped(const ClippedWeights& w, const Eigen::Vector3f& b) {
    return w.weights[0] * b[0] + w.weights[1] * b[1] + w.weights[2] * b[2];
}

// Pixels [x0, x1) x [y0, y1) of the visibility buffer, row stride `stride`.
struct TileTarget {
    int x0, y0, x1, y1, stride;
    float* depth;
    std::uint32_t* id;
};

// Rasterizes `t` (id `id`) into the tile: every pixel whose centre the fill
// rule assigns to it and that passes depth LESS (and `keep`, if given: the
// alpha test) gets depth and id.
using FragmentTest = std::function<bool(const ScreenTriangle& t, int x, int y)>;
void rasterize_triangle(const ScreenTriangle& t, std::uint32_t id, const TileTarget& tile,
                        const FragmentTest* keep);

// For blended triangles: calls `visit` for every pixel of the tile whose centre
// the fill rule assigns to `t` and whose depth passes LESS, writing nothing.
using PixelVisit = std::function<void(int x, int y, float depth)>;
void visit_triangle(const ScreenTriangle& t, const TileTarget& tile, const PixelVisit& visit);

// Pixel bounding box of a screen triangle, inclusive, clamped to the viewport
// and scissor. (Inline: binning calls it for every triangle.)
inline bool triangle_pixel_bounds(const ScreenTriangle& t, const Viewport& viewport, int& x0, int& y0,
                                  int& x1, int& y1) {
    const std::int32_t half = 1 << (subpixel_bits - 1);
    std::int32_t min_x = std::min({t.x[0], t.x[1], t.x[2]}), max_x = std::max({t.x[0], t.x[1], t.x[2]});
    std::int32_t min_y = std::min({t.y[0], t.y[1], t.y[2]}), max_y = std::max({t.y[0], t.y[1], t.y[2]});
    // Pixel x is a candidate when its centre x * 256 + 128 lies in [min_x, max_x].
    x0 = std::max({(min_x - half + (1 << subpixel_bits) - 1) >> subpixel_bits, 0, viewport.scissor_x0});
    y0 = std::max({(min_y - half + (1 << subpixel_bits) - 1) >> subpixel_bits, 0, viewport.scissor_y0});
    x1 = std::min({(max_x - half) >> subpixel_bits, viewport.width - 1, viewport.scissor_x1 - 1});
    y1 = std::min({(max_y - half) >> subpixel_bits, viewport.height - 1, viewport.scissor_y1 - 1});
    return x0 <= x1 && y0 <= y1;
}

}  // namespace boxlod
