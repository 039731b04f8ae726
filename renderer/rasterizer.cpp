#include "renderer/rasterizer.h"

#include "renderer/lanes.h"

#include <algorithm>
#include <cmath>

namespace boxlod {
namespace {

// Guard band: x and y are clipped only at +-guard_band * w, far outside the
// screen, so almost no triangle needs clipping there; it keeps snapped
// coordinates inside int32 for viewports up to 16k pixels.
constexpr float guard_band = 16;
constexpr int max_polygon = 9;  // a triangle clipped by 6 planes

struct ClipVertex {
    Eigen::Vector4f position;
    Eigen::Vector3f weights;  // barycentric weights of the source triangle
};

float plane_distance(const Eigen::Vector4f& v, int plane) {
    switch (plane) {
    case 0: return v.z() + v.w();  // near
    case 1: return v.w() - v.z();  // far
    case 2: return v.x() + guard_band * v.w();
    case 3: return guard_band * v.w() - v.x();
    case 4: return v.y() + guard_band * v.w();
    default: return guard_band * v.w() - v.y();
    }
}

// Sutherland-Hodgman against one plane; returns the new vertex count.
int clip_polygon(const ClipVertex* in, int count, int plane, ClipVertex* out) {
    int n = 0;
    for (int i = 0; i < count; ++i) {
        const ClipVertex& a = in[i];
        const ClipVertex& b = in[(i + 1) % count];
        float da = plane_distance(a.position, plane), db = plane_distance(b.position, plane);
        if (da >= 0) out[n++] = a;
        if ((da >= 0) != (db >= 0)) {
            float t = da / (da - db);
            out[n++] = {a.position + (b.position - a.position) * t, a.weights + (b.weights - a.weights) * t};
        }
    }
    return n;
}

std::int64_t edge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t px,
                  std::int64_t py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

std::int64_t doubled_area(const ScreenTriangle& t) {
    return edge(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
}

// A clip-space point's snapped window position, depth and 1/w (docs/design.md: Rendering).
void snap(const Eigen::Vector4f& p, const Viewport& viewport, ProjectedVertex& v) {
    const float scale = float(1 << subpixel_bits);
    v.inv_w = 1 / p.w();
    float wx = (p.x() * v.inv_w + 1) * 0.5f * float(viewport.width);
    float wy = (1 - p.y() * v.inv_w) * 0.5f * float(viewport.height);
    v.x = std::int32_t(std::floor(wx * scale + 0.5f));
    v.y = std::int32_t(std::floor(wy * scale + 0.5f));
    v.z = std::clamp((p.z() * v.inv_w + 1) * 0.5f, 0.0f, 1.0f);
}

// Whether [low, high] (subpixels) holds the centre of a pixel in [first, end).
[[gnu::always_inline]] inline bool holds_pixel_centre(std::int64_t low, std::int64_t high, int first,
                                                      int end) {
    const std::int64_t half = 1 << (subpixel_bits - 1), one = 1 << subpixel_bits;
    const std::int64_t k0 = std::max<std::int64_t>((low - half + one - 1) >> subpixel_bits, first);  // ceil
    const std::int64_t k1 =
        std::min<std::int64_t>((high - half) >> subpixel_bits, std::int64_t(end) - 1);  // floor
    return k0 <= k1;
}

// Appends the triangle of three snapped corners unless it has no area, faces
// the culled way, or its bounding box holds no pixel centre the viewport
// writes (it would cover none: most triangles of a far, detailed scene).
[[gnu::always_inline]] inline bool append_triangle(const ProjectedVertex& a, const ProjectedVertex& b,
                                                   const ProjectedVertex& c, std::uint32_t batch,
                                                   std::uint32_t triangle, Culling culling,
                                                   const Viewport& viewport,
                                                   std::vector<ScreenTriangle>& out) {
    std::int64_t area = edge(a.x, a.y, b.x, b.y, c.x, c.y);  // doubled_area of the triangle to be
    if (area == 0) return false;
    if (!holds_pixel_centre(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), viewport.scissor_x0,
                            std::min(viewport.width, viewport.scissor_x1)) ||
        !holds_pixel_centre(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), viewport.scissor_y0,
                            std::min(viewport.height, viewport.scissor_y1)))
        return false;
    // Counter-clockwise in NDC (y up) is negative area in window space (y down).
    bool front = area < 0;
    if ((culling == Culling::back && !front) || (culling == Culling::front && front)) return false;
    // Filled in place: a copy built on the stack and then stored whole made
    // the CPU wait on every triangle (its wide loads could not be forwarded
    // from the narrow stores that built it).
    ScreenTriangle& t = out.emplace_back();
    const ProjectedVertex* corner[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i) {
        t.x[i] = corner[i]->x;
        t.y[i] = corner[i]->y;
        t.z[i] = corner[i]->z;
        t.inv_w[i] = corner[i]->inv_w;
    }
    t.batch = batch;
    t.triangle = triangle;
    return true;
}

// The few triangles that cross a plane of the view volume.
[[gnu::noinline]] void clip_and_append(const Eigen::Vector4f clip[3], int outside_any, std::uint32_t batch,
                                       std::uint32_t triangle, Culling culling, const Viewport& viewport,
                                       std::vector<ScreenTriangle>& out,
                                       std::vector<ClippedWeights>& weights) {
    ClipVertex buffers[2][max_polygon];
    ClipVertex* polygon = buffers[0];
    int count = 3;
    for (int i = 0; i < 3; ++i) polygon[i] = {clip[i], Eigen::Vector3f::Unit(i)};
    for (int plane = 0; plane < 6 && count >= 3; ++plane) {
        if (!(outside_any & (1 << plane))) continue;
        ClipVertex* next = polygon == buffers[0] ? buffers[1] : buffers[0];
        count = clip_polygon(polygon, count, plane, next);
        polygon = next;
    }
    if (count < 3) return;
    ProjectedVertex snapped[max_polygon];
    for (int i = 0; i < count; ++i) snap(polygon[i].position, viewport, snapped[i]);
    for (int k = 1; k + 1 < count; ++k) {  // a fan over the clipped polygon
        if (!append_triangle(snapped[0], snapped[k], snapped[k + 1], batch, triangle, culling, viewport, out))
            continue;
        out.back().clipped = std::int32_t(weights.size());
        weights.push_back({{polygon[0].weights, polygon[k].weights, polygon[k + 1].weights}});
    }
}

// One triangle of setup_triangles, inlined into its loop; `clip_of` gives
// the corners' clip-space positions when the triangle must be clipped.
template <typename ClipOf>
[[gnu::always_inline]] inline void set_up(const ProjectedVertex* corner[3], const ClipOf& clip_of,
                                          std::uint32_t batch, std::uint32_t triangle, Culling culling,
                                          const Viewport& viewport, std::vector<ScreenTriangle>& out,
                                          std::vector<ClippedWeights>& weights) {
    const int outside_all = corner[0]->outcode & corner[1]->outcode & corner[2]->outcode;
    const int outside_any = corner[0]->outcode | corner[1]->outcode | corner[2]->outcode;
    if (outside_all) return;
    // Inside every plane (nearly every triangle): the corners as the vertex stage snapped them.
    if (!outside_any) {
        append_triangle(*corner[0], *corner[1], *corner[2], batch, triangle, culling, viewport, out);
        return;
    }
    Eigen::Vector4f clip[3];
    clip_of(clip);
    clip_and_append(clip, outside_any, batch, triangle, culling, viewport, out, weights);
}

}  // namespace

ProjectedVertex project_vertex(const Eigen::Vector4f& clip, const Viewport& viewport) {
    ProjectedVertex v;
    for (int plane = 0; plane < 6; ++plane)
        if (!(plane_distance(clip, plane) >= 0)) v.outcode |= 1 << plane;  // NaN counts as outside
    if (v.outcode == 0) snap(clip, viewport, v);
    return v;
}

void setup_triangles(const ProjectedMesh& mesh, std::size_t begin, std::size_t end, std::uint32_t batch,
                     Culling culling, const Viewport& viewport, std::vector<ScreenTriangle>& out,
                     std::vector<ClippedWeights>& weights) {
    // Locals: stores to `out` cannot make the compiler reload them.
    const std::uint32_t* const indices = mesh.indices;
    const ProjectedVertex* const vertices = mesh.vertices;
    for (std::size_t t = begin; t < end; ++t) {
        const std::uint32_t* v = indices + t * 3;
        const ProjectedVertex* corners[3] = {&vertices[v[0]], &vertices[v[1]], &vertices[v[2]]};
        auto clip_of = [&](Eigen::Vector4f clip[3]) {
            for (int k = 0; k < 3; ++k) clip[k] = clip_position(*mesh.to_clip, mesh.positions[v[k]]);
        };
        set_up(corners, clip_of, batch, std::uint32_t(t), culling, viewport, out, weights);
    }
}

void setup_triangle(const Eigen::Vector4f clip[3], std::uint32_t batch, std::uint32_t triangle,
                    Culling culling, const Viewport& viewport, std::vector<ScreenTriangle>& out,
                    std::vector<ClippedWeights>& weights) {
    const ProjectedVertex projected[3] = {project_vertex(clip[0], viewport),
                                          project_vertex(clip[1], viewport),
                                          project_vertex(clip[2], viewport)};
    const ProjectedVertex* corners[3] = {&projected[0], &projected[1], &projected[2]};
    auto clip_of = [&](Eigen::Vector4f out_clip[3]) { std::copy(clip, clip + 3, out_clip); };
    set_up(corners, clip_of, batch, triangle, culling, viewport, out, weights);
}

namespace {
// The set-up without the clipped triangle's weights (screen barycentrics need none).
BarycentricSetup screen_setup(const ScreenTriangle& t) {
    const double s = 1.0 / (1 << subpixel_bits);
    BarycentricSetup b;
    b.x0 = t.x[0] * s;
    b.y0 = t.y[0] * s;
    b.x1 = t.x[1] * s;
    b.y1 = t.y[1] * s;
    b.x2 = t.x[2] * s;
    b.y2 = t.y[2] * s;
    b.area = (b.x1 - b.x0) * (b.y2 - b.y0) - (b.y1 - b.y0) * (b.x2 - b.x0);
    for (int i = 0; i < 3; ++i) b.inv_w[i] = t.inv_w[i];
    return b;
}
}  // namespace

BarycentricSetup barycentric_setup(const ScreenTriangle& t, const std::vector<ClippedWeights>& weights) {
    BarycentricSetup b = screen_setup(t);
    if (t.clipped >= 0) b.clipped = &weights[std::size_t(t.clipped)];
    return b;
}

Eigen::Vector3d screen_barycentrics(const BarycentricSetup& s, double px, double py) {
    double l0 = ((s.x2 - s.x1) * (py - s.y1) - (s.y2 - s.y1) * (px - s.x1)) / s.area;
    double l1 = ((s.x0 - s.x2) * (py - s.y2) - (s.y0 - s.y2) * (px - s.x2)) / s.area;
    return {l0, l1, 1 - l0 - l1};
}

Eigen::Vector3d screen_barycentrics(const ScreenTriangle& t, double px, double py) {
    return screen_barycentrics(screen_setup(t), px, py);
}

Eigen::Vector3f source_barycentrics(const BarycentricSetup& s, double px, double py) {
    Eigen::Vector3d l = screen_barycentrics(s, px, py);
    Eigen::Vector3d q(l[0] * s.inv_w[0], l[1] * s.inv_w[1], l[2] * s.inv_w[2]);
    double sum = q.sum();
    Eigen::Vector3f b = sum != 0 ? Eigen::Vector3f((q / sum).cast<float>()) : Eigen::Vector3f(1, 0, 0);
    if (!s.clipped) return b;
    return source_of_clipped(*s.clipped, b);
}

Eigen::Vector3f source_barycentrics(const ScreenTriangle& t, const std::vector<ClippedWeights>& weights,
                                    double px, double py) {
    return source_barycentrics(barycentric_setup(t, weights), px, py);
}

namespace {

// The pixels of one tile whose centres lie in a triangle's bounding box.
struct PixelBox {
    std::int64_t width, height;  // of the bounding box, in subpixels
    int x0, y0, x1, y1;          // the pixels to walk, inclusive
    bool cut_by_tile;            // x0 or x1 is the tile's, inside the triangle's own bounds
};

// False when the box holds no pixel centre of the tile. (Inline: called, it
// cost each small triangle 12 instructions more.)
[[gnu::always_inline]] inline bool pixel_box(const ScreenTriangle& t, const TileTarget& tile, PixelBox& b) {
    const std::int64_t min_x = std::min({t.x[0], t.x[1], t.x[2]}), max_x = std::max({t.x[0], t.x[1], t.x[2]});
    const std::int64_t min_y = std::min({t.y[0], t.y[1], t.y[2]}), max_y = std::max({t.y[0], t.y[1], t.y[2]});
    const std::int32_t half = 1 << (subpixel_bits - 1), one = 1 << subpixel_bits;
    const int own_x0 = int((min_x - half + one - 1) >> subpixel_bits),
              own_x1 = int((max_x - half) >> subpixel_bits);
    b.width = max_x - min_x;
    b.height = max_y - min_y;
    b.x0 = std::max(own_x0, tile.x0);
    b.y0 = std::max<int>(int((min_y - half + one - 1) >> subpixel_bits), tile.y0);
    b.x1 = std::min(own_x1, tile.x1 - 1);
    b.cut_by_tile = b.x0 != own_x0 || b.x1 != own_x1;
    b.y1 = std::min<int>(int((max_y - half) >> subpixel_bits), tile.y1 - 1);
    return b.x0 <= b.x1 && b.y0 <= b.y1;
}

// A triangle's edge functions over its pixel box in one tile. Edge k runs
// from corner k+1 to corner k+2 (opposite corner k) of the triangle oriented
// to positive area; a pixel is inside when every E_k - bias_k >= 0, bias 0 on
// top and left edges and 1 elsewhere (the top-left fill rule).
struct EdgeSetup {
    int x0, y0, x1, y1;   // the pixels to walk, inclusive
    bool cut_by_tile;     // as in PixelBox
    std::int64_t row[3];  // E_k - bias_k at the centre of (x0, y0)
    std::int64_t step_x[3], step_y[3], bias[3];
    std::int64_t area;      // doubled, positive
    double z[3], inv_area;  // corner depths and 1 / area
};

// Depth from the exact edge values E_k (bias added back), w_k as doubles:
// the same at a pixel however the screen is split, and the one expression of
// every walk, a pixel or four at a time (T double or DoubleLanes).
template <typename T>
T depth_from(const double z[3], double inv_area, const T& w0, const T& w1, const T& w2) {
    return (w0 * z[0] + w1 * z[1] + w2 * z[2]) * inv_area;
}

double depth_of(const EdgeSetup& s, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
    return depth_from(s.z, s.inv_area, double(e0 + s.bias[0]), double(e1 + s.bias[1]),
                      double(e2 + s.bias[2]));
}

void floor_divide(std::int64_t a, std::int64_t b, std::int64_t& quotient, std::int64_t& remainder) {
    quotient = a / b;
    if (a % b != 0 && (a < 0) != (b < 0)) --quotient;
    remainder = a - quotient * b;
}

// The edge functions of `t` over the pixels of `box`.
void edge_setup(const ScreenTriangle& t, const PixelBox& box, EdgeSetup& s) {
    std::int64_t area = doubled_area(t);
    int o[3] = {0, 1, 2};  // corner i here is corner o[i] of the stored triangle
    if (area < 0) std::swap(o[1], o[2]), area = -area;
    const std::int64_t X[3] = {t.x[o[0]], t.x[o[1]], t.x[o[2]]}, Y[3] = {t.y[o[0]], t.y[o[1]], t.y[o[2]]};
    const std::int32_t half = 1 << (subpixel_bits - 1), one = 1 << subpixel_bits;
    s.x0 = box.x0;
    s.y0 = box.y0;
    s.x1 = box.x1;
    s.y1 = box.y1;
    s.cut_by_tile = box.cut_by_tile;
    const std::int64_t px = std::int64_t(s.x0) * one + half, py = std::int64_t(s.y0) * one + half;
    for (int k = 0; k < 3; ++k) {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        const std::int64_t dx = X[b] - X[a], dy = Y[b] - Y[a];
        // Top-left rule (y down): a left edge has dy < 0, a top edge dy == 0 and dx > 0.
        s.bias[k] = dy < 0 || (dy == 0 && dx > 0) ? 0 : 1;
        s.row[k] = edge(X[a], Y[a], X[b], Y[b], px, py) - s.bias[k];
        s.step_x[k] = -dy * one;
        s.step_y[k] = dx * one;
        s.z[k] = t.z[o[k]];
    }
    s.area = area;
    s.inv_area = 1.0 / double(area);
}

// A triangle under 8 pixels a side, the bulk of a dense distant mesh:
// edge_setup and walk_each_centre with the three edges in the lanes of one
// vector, each centre tested by one add. Its edge values stay below 2^24 in
// magnitude (each a sum of two products of factors below 2^11 + 2^8), so in
// 32-bit lanes they are edge_setup's integers exactly, and the depths its
// depths (docs/performance.md: Small triangles).
constexpr std::int64_t small_triangle = 8 << subpixel_bits;

template <int order>
IntLanes shuffled(IntLanes v) {
    return IntLanes(_mm_shuffle_epi32(__m128i(v), order));
}

template <typename OnPixel>
void walk_small_triangle(const ScreenTriangle& t, const PixelBox& box, const TileTarget& tile,
                         OnPixel& on_pixel) {
    static_assert(offsetof(ScreenTriangle, y) == offsetof(ScreenTriangle, x) + 12 &&
                  offsetof(ScreenTriangle, z) == offsetof(ScreenTriangle, y) + 12);
    // Corners in lanes 0-2 (lane 3 reads the next field; the shuffles below drop it).
    IntLanes X = IntLanes(_mm_loadu_si128(reinterpret_cast<const __m128i*>(t.x)));
    IntLanes Y = IntLanes(_mm_loadu_si128(reinterpret_cast<const __m128i*>(t.y)));
    std::int64_t area = doubled_area(t);
    const bool swapped = area < 0;  // oriented to positive area as in edge_setup
    constexpr int swap_1_2 = _MM_SHUFFLE(3, 1, 2, 0), from = _MM_SHUFFLE(0, 0, 2, 1),
                  to = _MM_SHUFFLE(0, 1, 0, 2);
    if (swapped) X = shuffled<swap_1_2>(X), Y = shuffled<swap_1_2>(Y), area = -area;
    // Lane k: edge k, from corner k + 1 to corner k + 2 (lane 3: corner 0 to itself).
    const IntLanes ax = shuffled<from>(X), ay = shuffled<from>(Y), dx = shuffled<to>(X) - ax,
                   dy = shuffled<to>(Y) - ay;
    const IntLanes bias = ((dy < 0) | ((dy == 0) & (dx > 0))) + 1;  // 0 on top and left edges
    const std::int32_t half = 1 << (subpixel_bits - 1), one = 1 << subpixel_bits;
    const IntLanes px = IntLanes{} + (box.x0 * one + half), py = IntLanes{} + (box.y0 * one + half);
    const IntLanes step_x = -dy * one, step_y = dx * one;
    IntLanes row = dx * (py - ay) - dy * (px - ax) - bias;
    const double z[3] = {t.z[0], t.z[swapped ? 2 : 1], t.z[swapped ? 1 : 2]}, inv_area = 1.0 / double(area);
    for (int y = box.y0; y <= box.y1; ++y, row += step_y) {
        float* depth = tile.depth + std::size_t(y - tile.y0) * tile.stride;
        std::uint32_t* ids = tile.id + std::size_t(y - tile.y0) * tile.stride;
        IntLanes e = row;
        for (int x = box.x0; x <= box.x1; ++x, e += step_x) {
            if (_mm_movemask_ps(__m128(e)) & 7) continue;  // some E_k - bias_k < 0: outside
            const IntLanes w = e + bias;
            const float depth_here = float(depth_from(z, inv_area, double(w[0]), double(w[1]), double(w[2])));
            const int i = x - tile.x0;
            if (depth_here < depth[i]) on_pixel(x, y, depth_here, depth[i], ids[i]);
        }
    }
}

// Narrows rows y0..y1 to those where value + (y - top) step >= 0.
void keep_rows_where(std::int64_t value, std::int64_t step, int top, int& y0, int& y1) {
    std::int64_t rows, unused;
    if (step > 0) {
        floor_divide(-value + step - 1, step, rows, unused);  // the first: ceil(-value / step)
        y0 = int(std::max<std::int64_t>(y0, top + std::min<std::int64_t>(rows, y1 - top + 1)));
    } else if (step < 0) {
        floor_divide(value, -step, rows, unused);  // the last: floor(value / -step)
        y1 = int(std::min<std::int64_t>(y1, top + std::max<std::int64_t>(rows, -1)));
    } else if (value < 0) {
        y1 = y0 - 1;
    }
}

// Narrow triangles: every pixel centre tested.
template <typename OnPixel>
void walk_each_centre(const EdgeSetup& s, const TileTarget& tile, OnPixel& on_pixel) {
    std::int64_t row[3] = {s.row[0], s.row[1], s.row[2]};
    for (int y = s.y0; y <= s.y1; ++y) {
        std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        float* depth = tile.depth + std::size_t(y - tile.y0) * tile.stride;
        std::uint32_t* ids = tile.id + std::size_t(y - tile.y0) * tile.stride;
        for (int x = s.x0; x <= s.x1; ++x) {
            if ((e0 | e1 | e2) >= 0) {
                const float z = float(depth_of(s, e0, e1, e2));
                const int i = x - tile.x0;
                if (z < depth[i]) on_pixel(x, y, z, depth[i], ids[i]);
            }
            e0 += s.step_x[0];
            e1 += s.step_x[1];
            e2 += s.step_x[2];
        }
        for (int k = 0; k < 3; ++k) row[k] += s.step_y[k];
    }
}

// One sloped edge's bound on every row's run of inside pixels, solved from
// E(x) = E(x0) + (x - x0) step_x >= 0 in exact integers: with m = |step_x|,
// E(x0) = f m + r (0 <= r < m), so a left edge (step_x > 0) admits x >= x0 - f
// and a right edge x <= x0 + f. A row down adds step_y = fb m + rb: the
// division is carried from row to row, not redone.
struct RunBound {
    std::int64_t f, r, m, fb, rb;
    void next_row() {
        f += fb;
        r += rb;
        if (r >= m) {
            r -= m;
            ++f;
        }
    }
};

// Where every |E| of the walked pixels stays below 2^50, E + n step_x is an
// exact double for the few n of a group of four, so depths computed four at a
// time in doubles have depth_of's bits. E is linear: its corners bound it.
bool exact_in_doubles(const EdgeSetup& s) {
    const std::int64_t limit = std::int64_t(1) << 50, width = s.x1 - s.x0, height = s.y1 - s.y0;
    for (int k = 0; k < 3; ++k)
        for (std::int64_t corner : {std::int64_t(0), width * s.step_x[k], height * s.step_y[k],
                                    width * s.step_x[k] + height * s.step_y[k]}) {
            const std::int64_t e = s.row[k] + s.bias[k] + corner;
            if (e <= -limit || e >= limit) return false;
        }
    return true;
}

// The runs firsts[n]..lasts[n] of rows top + n, their depths four pixels at a
// time: E_0 and E_1 in doubles, E_2 = doubled area - E_0 - E_1 (the three sum
// to it), every one an integer below 2^50 (exact_in_doubles), so exact.
template <typename OnPixel>
void walk_runs_in_lanes(const EdgeSetup& s, int top, int rows, const std::int32_t* firsts,
                        const std::int32_t* lasts, const TileTarget& tile, OnPixel& on_pixel) {
    double row0 = double(s.row[0] + s.bias[0] + (top - s.y0) * s.step_y[0]);
    double row1 = double(s.row[1] + s.bias[1] + (top - s.y0) * s.step_y[1]);
    const double step_x0 = double(s.step_x[0]), step_x1 = double(s.step_x[1]), area = double(s.area);
    // Lane j of a group starts at E + j step_x; a group on adds 4 step_x.
    const DoubleLanes offset0{_mm_setr_pd(0, step_x0), _mm_setr_pd(2 * step_x0, 3 * step_x0)},
        offset1{_mm_setr_pd(0, step_x1), _mm_setr_pd(2 * step_x1, 3 * step_x1)};
    const DoubleLanes group0 = broadcast(4 * step_x0), group1 = broadcast(4 * step_x1);
    for (int n = 0; n < rows; ++n, row0 += double(s.step_y[0]), row1 += double(s.step_y[1])) {
        const int first = firsts[n], last = lasts[n], y = top + n;
        if (first > last) continue;
        float* depth = tile.depth + std::size_t(y - tile.y0) * tile.stride + (first - tile.x0);
        std::uint32_t* ids = tile.id + std::size_t(y - tile.y0) * tile.stride + (first - tile.x0);
        const double offset = first - s.x0;
        DoubleLanes e0 = broadcast(row0 + offset * step_x0) + offset0,
                    e1 = broadcast(row1 + offset * step_x1) + offset1;
        for (int x = first; x <= last; x += 4, depth += 4, ids += 4) {
            const DoubleLanes e2 = area - e0 - e1;
            const FloatLanes z = to_floats(depth_from(s.z, s.inv_area, e0, e1, e2));
            const int count = std::min(last - x + 1, 4);
            // A row's last group may reach past the tile's row: then only its pixels are read.
            const FloatLanes old = x + 3 < tile.x1 ? _mm_loadu_ps(depth)
                                                   : from_scalars(depth[0], count > 1 ? depth[1] : 0,
                                                                  count > 2 ? depth[2] : 0, 0);
            for (int passed = _mm_movemask_ps(_mm_cmplt_ps(z, old)) & ((1 << count) - 1); passed;
                 passed &= passed - 1) {
                const int j = __builtin_ctz(unsigned(passed));
                on_pixel(x + j, y, z[j], depth[j], ids[j]);
            }
            e0 = e0 + group0;
            e1 = e1 + group1;
        }
    }
}

// The same runs where some E reaches 2^50: depth_of at each pixel.
template <typename OnPixel>
void walk_runs(const EdgeSetup& s, int top, int rows, const std::int32_t* firsts, const std::int32_t* lasts,
               const TileTarget& tile, OnPixel& on_pixel) {
    for (int n = 0; n < rows; ++n) {
        const int y = top + n;
        float* depth = tile.depth + std::size_t(y - tile.y0) * tile.stride;
        std::uint32_t* ids = tile.id + std::size_t(y - tile.y0) * tile.stride;
        std::int64_t e[3];
        for (int k = 0; k < 3; ++k)
            e[k] = s.row[k] + (y - s.y0) * s.step_y[k] + (firsts[n] - s.x0) * s.step_x[k];
        for (int x = firsts[n]; x <= lasts[n]; ++x) {
            const float z = float(depth_of(s, e[0], e[1], e[2]));
            const int i = x - tile.x0;
            if (z < depth[i]) on_pixel(x, y, z, depth[i], ids[i]);
            for (int k = 0; k < 3; ++k) e[k] += s.step_x[k];
        }
    }
}

// Wide triangles: each row's run of inside pixels solved from its `Left` and
// `Right` bounding edges (s.y0..s.y1 are the rows a horizontal edge admits),
// in a loop of its own that keeps the bounds in registers, then walked.
template <int Left, int Right, typename OnPixel>
void walk_solved_runs(const EdgeSetup& s, const RunBound* left_bounds, const RunBound* right_bounds,
                      const TileTarget& tile, OnPixel& on_pixel) {
    RunBound left[Left], right[Right];
    std::copy(left_bounds, left_bounds + Left, left);
    std::copy(right_bounds, right_bounds + Right, right);
    const bool in_lanes = exact_in_doubles(s);
    constexpr int chunk = 64;  // rows solved at a time: a tile's
    std::int32_t firsts[chunk], lasts[chunk];
    for (int top = s.y0; top <= s.y1; top += chunk) {
        const int rows = std::min(chunk, s.y1 - top + 1);
        for (int n = 0; n < rows; ++n) {
            std::int64_t first = s.x0, last = s.x1;
            for (const RunBound& bound : left) first = std::max(first, s.x0 - bound.f);
            for (const RunBound& bound : right) last = std::min(last, s.x0 + bound.f);
            firsts[n] = std::int32_t(std::min<std::int64_t>(first, s.x1 + 1));  // an empty run stays in int
            lasts[n] = std::int32_t(std::max<std::int64_t>(last, s.x0 - 1));
            for (RunBound& bound : left) bound.next_row();
            for (RunBound& bound : right) bound.next_row();
        }
        if (in_lanes)
            walk_runs_in_lanes(s, top, rows, firsts, lasts, tile, on_pixel);
        else
            walk_runs(s, top, rows, firsts, lasts, tile, on_pixel);
    }
}

// Walks the pixels of `t` in the tile that the fill rule gives it and that pass
// depth LESS; `on_pixel(x, y, depth, depth_slot, id_slot)` decides what to write.
template <typename OnPixel>
void walk_triangle(const ScreenTriangle& t, const TileTarget& tile, OnPixel&& on_pixel) {
    PixelBox box;
    if (!pixel_box(t, tile, box)) return;
    if (box.width < small_triangle && box.height < small_triangle)
        return walk_small_triangle(t, box, tile, on_pixel);
    EdgeSetup s;
    edge_setup(t, box, s);
    if (s.x1 - s.x0 < 7) return walk_each_centre(s, tile, on_pixel);
    // Only rows where some pixel of the bounds is inside every edge can hold a
    // run: those where E_k at the bounds' column farthest inside it is >= 0.
    // Such rows are a range per edge, E being linear in y. It matters for a
    // bottom edge (its row's centres are outside) and, where the tile cut the
    // bounds left or right, for sloped edges (rows of the triangle beside the tile).
    const int top = s.y0;
    for (int k = 0; k < 3; ++k) {
        if (s.step_x[k] != 0 && !s.cut_by_tile) continue;
        const std::int64_t widest = s.row[k] + (s.step_x[k] > 0 ? (s.x1 - s.x0) * s.step_x[k] : 0);
        keep_rows_where(widest, s.step_y[k], top, s.y0, s.y1);
    }
    if (s.y0 > s.y1) return;
    RunBound left[2], right[2];
    int left_count = 0, right_count = 0;
    for (int k = 0; k < 3; ++k) {
        s.row[k] += std::int64_t(s.y0 - top) * s.step_y[k];
        if (s.step_x[k] == 0) continue;
        RunBound& bound = s.step_x[k] > 0 ? left[left_count++] : right[right_count++];
        bound.m = std::abs(s.step_x[k]);
        floor_divide(s.row[k], bound.m, bound.f, bound.r);
        floor_divide(s.step_y[k], bound.m, bound.fb, bound.rb);
    }
    // Positive area: two sloped edges on one side and one on the other, or one
    // on each side of a horizontal edge.
    if (left_count == 2) return walk_solved_runs<2, 1>(s, left, right, tile, on_pixel);
    if (right_count == 2) return walk_solved_runs<1, 2>(s, left, right, tile, on_pixel);
    walk_solved_runs<1, 1>(s, left, right, tile, on_pixel);
}

}  // namespace

void rasterize_triangle(const ScreenTriangle& t, std::uint32_t id, const TileTarget& tile,
                        const FragmentTest* keep) {
    // Two walks: without a test, no call in the loop makes the compiler keep its lanes in memory.
    if (!keep)
        return walk_triangle(t, tile, [id](int, int, float depth, float& depth_slot, std::uint32_t& id_slot) {
            depth_slot = depth;
            id_slot = id;
        });
    walk_triangle(t, tile, [&](int x, int y, float depth, float& depth_slot, std::uint32_t& id_slot) {
        if (!(*keep)(t, x, y)) return;
        depth_slot = depth;
        id_slot = id;
    });
}

void visit_triangle(const ScreenTriangle& t, const TileTarget& tile, const PixelVisit& visit) {
    walk_triangle(t, tile, [&](int x, int y, float depth, float&, std::uint32_t&) { visit(x, y, depth); });
}

}  // namespace boxlod
