// The pipeline (docs/design.md: Rendering): vertex stage, clipping and set-up,
// binning to tiles, a visibility buffer per tile, then one Fragment per visible
// pixel handed to the Shader (renderer/shading.h).
#include "renderer/renderer.h"

#include "base/memory_budget.h"
#include "base/parallel.h"
#include "renderer/lanes.h"
#include "renderer/shading.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace boxlod {

Frame make_frame(int width, int height, const Eigen::Vector3f& background) {
    constexpr double frame_bytes_per_pixel = sizeof(Eigen::Vector4f) + sizeof(float) + sizeof(Eigen::Vector3f);
    const double bytes = frame_bytes_per_pixel * double(width) * double(height);
    // The message only when refused: small frames are made by the thousand (hybrid.h).
    if (bytes > memory_budget()) check_memory("a " + std::to_string(width) + " x " + std::to_string(height) + " frame", bytes);
    Frame frame;
    frame.width = width;
    frame.height = height;
    std::size_t n = std::size_t(width) * height;
    frame.color.assign(n, Eigen::Vector4f(background.x(), background.y(), background.z(), 0));
    frame.depth.assign(n, std::numeric_limits<float>::infinity());
    frame.normal.assign(n, Eigen::Vector3f::Zero());
    return frame;
}

double render_memory(int width, int height) { return 40.0 * double(width) * double(height); }

namespace {

constexpr int tile_bits = 6, tile_size = 1 << tile_bits;
constexpr std::size_t triangles_per_chunk = 1 << 15;
constexpr int chunk_index_bits = 19;  // a chunk of 2^15 triangles clips into at most 7 * 2^15 < 2^19 pieces

// Columns x0..x1 and rows y0..y1 of tiles, inclusive.
struct TileRange {
    int x0, y0, x1, y1;
};

// Screen triangles of one chunk of the input, binned to tiles (CSR layout).
struct Chunk {
    std::vector<ScreenTriangle> triangles;
    std::vector<ClippedWeights> weights;
    std::vector<std::uint32_t> bin_start;  // per tile, into bin_items; size tiles + 1
    std::vector<std::uint32_t> bin_items;  // triangle indices within this chunk, in submission order
    std::vector<TileRange> tiles_of;         // scratch while binning: the tiles of each triangle
    std::vector<std::uint32_t> tile_counts;  // and the triangles of each tile
};

struct Tiling {
    int columns, rows;
    int count() const { return columns * rows; }
};

struct Context {
    const std::vector<Batch>& batches;
    const RenderSettings& settings;
    const std::vector<Chunk>& chunks;
    std::size_t chunk_count;  // chunks in use this frame (the scratch may hold more)
    const Shader& shader;
};

const ScreenTriangle& triangle_of(const Context& c, std::uint32_t id, const std::vector<ClippedWeights>*& weights) {
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

// The gradients g of u and v in the plane of a triangle with edges e1, e2
// and uv changes d1, d2 along them: g . e1 = d1 and g . e2 = d2, so
// g = [e1 e2] G^-1 d (G the edges' Gram matrix). False for a degenerate
// triangle. Out of line, from the mesh: only metric parallax needs it, and
// inlined its registers would cost every other triangle's setup.
[[gnu::noinline]] bool uv_gradient_of(const Mesh& mesh, const std::uint32_t* v, UvGradient& gradient) {
    const Eigen::Vector3f e1 = mesh.positions[v[1]] - mesh.positions[v[0]], e2 = mesh.positions[v[2]] - mesh.positions[v[0]];
    const Eigen::Vector2f d1 = mesh.uvs[v[1]] - mesh.uvs[v[0]], d2 = mesh.uvs[v[2]] - mesh.uvs[v[0]];
    float a = e1.dot(e1), b = e1.dot(e2), d = e2.dot(e2), det = a * d - b * b;
    if (!(det > 0)) return false;
    gradient.du_dposition = (e1 * (d * d1.x() - b * d2.x()) + e2 * (a * d2.x() - b * d1.x())) / det;
    gradient.dv_dposition = (e1 * (d * d1.y() - b * d2.y()) + e2 * (a * d2.y() - b * d1.y())) / det;
    return true;
}

void set_up_triangle(const Context& c, std::uint32_t id, TriangleSetup& s) {
    const std::vector<ClippedWeights>* weights;
    s.screen = &triangle_of(c, id, weights);
    s.batch = &c.batches[s.screen->batch];
    const Mesh& mesh = *s.batch->mesh;
    s.v = &mesh.indices[std::size_t(s.screen->triangle) * 3];
    s.barycentrics = barycentric_setup(*s.screen, *weights);
    const Eigen::Vector3f &p0 = mesh.positions[s.v[0]], &p1 = mesh.positions[s.v[1]], &p2 = mesh.positions[s.v[2]];
    const Eigen::Vector3f e1 = p1 - p0, e2 = p2 - p0;
    s.geometric_normal = e1.cross(e2);
    float length = s.geometric_normal.norm();
    s.geometric_normal = length > 0 ? Eigen::Vector3f(s.geometric_normal / length) : Eigen::Vector3f(0, 0, 1);
    s.has_uv_frame = s.has_uv_gradient = false;
    if (mesh.uvs.empty()) return;
    if (mesh.tangents.empty()) {
        const Eigen::Vector2f &u0 = mesh.uvs[s.v[0]], &u1 = mesh.uvs[s.v[1]], &u2 = mesh.uvs[s.v[2]];
        Eigen::Vector2f d1 = u1 - u0, d2 = u2 - u0;
        float det = d1.x() * d2.y() - d2.x() * d1.y();
        if (det != 0) {
            s.has_uv_frame = true;
            s.uv_tangent = (e1 * d2.y() - e2 * d1.y()) / det;
            s.uv_bitangent = (e2 * d1.x() - e1 * d2.x()) / det;
        }
    }
    const Surface& surface = s.batch->surface;
    if (surface.height && surface.height_depth > 0) s.has_uv_gradient = uv_gradient_of(mesh, s.v, s.uv_gradient);
}

Fragment make_fragment(const TriangleSetup& s, int x, int y, bool reads_uv) {
    const Mesh& mesh = *s.batch->mesh;
    const std::uint32_t* v = s.v;
    double px = x + 0.5, py = y + 0.5;
    Eigen::Vector3f b = source_barycentrics(s.barycentrics, px, py);
    Fragment f;
    f.position = mesh.positions[v[0]] * b[0] + mesh.positions[v[1]] * b[1] + mesh.positions[v[2]] * b[2];
    f.geometric_normal = s.geometric_normal;
    f.normal = f.geometric_normal;
    if (!mesh.normals.empty()) {
        Eigen::Vector3f n = interpolate(mesh.normals, v, b);
        if (n.squaredNorm() > 0) f.normal = n.normalized();
    }
    if (reads_uv && !mesh.uvs.empty()) {
        f.has_uv = true;
        f.uv = interpolate(mesh.uvs, v, b);
        f.duv_dx = interpolate(mesh.uvs, v, source_barycentrics(s.barycentrics, px + 1, py)) - f.uv;
        f.duv_dy = interpolate(mesh.uvs, v, source_barycentrics(s.barycentrics, px, py + 1)) - f.uv;
        if (s.has_uv_gradient) f.uv_gradient = &s.uv_gradient;
        if (!mesh.tangents.empty()) {
            Eigen::Vector4f t4 = interpolate(mesh.tangents, v, b);
            Eigen::Vector3f tangent = t4.head<3>();
            tangent -= f.normal * f.normal.dot(tangent);  // Gram-Schmidt against the shading normal
            if (tangent.squaredNorm() > 0) {
                f.tangent = tangent.normalized();
                f.bitangent = f.normal.cross(f.tangent) * (t4.w() < 0 ? -1.0f : 1.0f);
            }
        } else if (s.has_uv_frame) {
            Eigen::Vector3f tangent = s.uv_tangent;
            tangent -= f.normal * f.normal.dot(tangent);
            if (tangent.squaredNorm() > 0) {
                f.tangent = tangent.normalized();
                // The bitangent points up the image, against dp/dv (glTF: uv origin at the top left).
                float handedness = f.normal.cross(f.tangent).dot(s.uv_bitangent) > 0 ? -1.0f : 1.0f;
                f.bitangent = f.normal.cross(f.tangent) * handedness;
            }
        }
    }
    return f;
}

// What make_fragment_lanes reads of the triangles of lane_count pixels, in
// lanes: what set_up_triangle gathers and computes, with the same operations.
// Lanes past a group's count repeat its last pixel.
struct TriangleLanes {
    std::uint32_t ids[lane_count];
    DoubleLanes screen_x[3], screen_y[3], inv_w[3], area;  // barycentric_setup
    const ClippedWeights* clipped[lane_count];
    Vector3Lanes position[3], edge1, edge2, geometric_normal, normal[3];
    IntLanes has_normals;
    const Surface* surface[lane_count];
    bool any_uv = false;
};

// And what shaders that read uvs need besides.
struct TexturedTriangleLanes : TriangleLanes {
    IntLanes has_uv, has_tangents, has_uv_frame;
    FloatLanes u[3], v[3], tangent_w[3];
    Vector3Lanes tangent[3], uv_tangent, uv_bitangent;
    UvGradient uv_gradient[lane_count];
    const UvGradient* uv_gradient_of_lane[lane_count];
};

// A 4x4 transpose: out[i] holds element i of each row.
void transpose(__m128 r0, __m128 r1, __m128 r2, __m128 r3, FloatLanes* out) {
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    out[0] = r0, out[1] = r1, out[2] = r2, out[3] = r3;
}

// Three floats at each lane's pointer, read as two and one: no read past a vector's end.
Vector3Lanes gather(const Eigen::Vector3f* const* p) {
    __m128 r[lane_count];
    for (int j = 0; j < lane_count; ++j)
        r[j] = _mm_movelh_ps(load_two(p[j]->data()), _mm_load_ss(p[j]->data() + 2));
    FloatLanes lanes[4];
    transpose(r[0], r[1], r[2], r[3], lanes);
    return Vector3Lanes{lanes[0], lanes[1], lanes[2]};
}

// (A template on reads_uv: the untextured instance keeps no uv code.)
template <bool reads_uv>
using TrianglesOf = std::conditional_t<reads_uv, TexturedTriangleLanes, TriangleLanes>;

template <bool reads_uv>
[[gnu::always_inline]] inline void gather_triangles(const Context& c, const std::uint32_t ids[lane_count], TrianglesOf<reads_uv>& t) {
    static_assert(offsetof(ScreenTriangle, y) == offsetof(ScreenTriangle, x) + 12 &&
                  offsetof(ScreenTriangle, inv_w) + 16 <= sizeof(ScreenTriangle));
    static const Eigen::Vector3f no_normal = Eigen::Vector3f::Zero();
    static const Eigen::Vector2f no_uv = Eigen::Vector2f::Zero();
    static const Eigen::Vector4f no_tangent = Eigen::Vector4f::Zero();
    __m128i corners_x[lane_count], corners_y[lane_count];
    __m128 inv_w[lane_count];
    const Eigen::Vector3f *positions[3][lane_count], *normals[3][lane_count];
    const Eigen::Vector2f* uvs[3][lane_count];
    const Eigen::Vector4f* tangents[3][lane_count];
    t.any_uv = false;
    for (int j = 0; j < lane_count; ++j) {
        t.ids[j] = ids[j];
        const std::vector<ClippedWeights>* weights;
        const ScreenTriangle& screen = triangle_of(c, ids[j], weights);
        const auto* bytes = reinterpret_cast<const char*>(&screen);
        corners_x[j] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes + offsetof(ScreenTriangle, x)));
        corners_y[j] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes + offsetof(ScreenTriangle, y)));
        inv_w[j] = _mm_loadu_ps(reinterpret_cast<const float*>(bytes + offsetof(ScreenTriangle, inv_w)));
        t.clipped[j] = screen.clipped >= 0 ? &(*weights)[std::size_t(screen.clipped)] : nullptr;
        const Batch& batch = c.batches[screen.batch];
        const Mesh& mesh = *batch.mesh;
        const std::uint32_t* v = &mesh.indices[std::size_t(screen.triangle) * 3];
        t.has_normals[j] = mesh.normals.empty() ? 0 : -1;
        for (int k = 0; k < 3; ++k) {
            positions[k][j] = &mesh.positions[v[k]];
            normals[k][j] = mesh.normals.empty() ? &no_normal : &mesh.normals[v[k]];
        }
        t.surface[j] = &batch.surface;
        if constexpr (reads_uv) {
            const bool with_uv = !mesh.uvs.empty(), with_tangents = with_uv && !mesh.tangents.empty();
            t.any_uv = t.any_uv || with_uv;
            t.has_uv[j] = with_uv ? -1 : 0;
            t.has_tangents[j] = with_tangents ? -1 : 0;
            for (int k = 0; k < 3; ++k) {
                uvs[k][j] = with_uv ? &mesh.uvs[v[k]] : &no_uv;
                tangents[k][j] = with_tangents ? &mesh.tangents[v[k]] : &no_tangent;
            }
            const Surface& surface = batch.surface;
            t.uv_gradient_of_lane[j] = nullptr;
            if (!with_uv || !surface.height || !(surface.height_depth > 0)) continue;
            if (j > 0 && ids[j] == ids[j - 1]) t.uv_gradient_of_lane[j] = t.uv_gradient_of_lane[j - 1];
            else if (uv_gradient_of(mesh, v, t.uv_gradient[j])) t.uv_gradient_of_lane[j] = &t.uv_gradient[j];
        }
    }
    FloatLanes lanes[4];
    const double scale = 1.0 / (1 << subpixel_bits);
    for (const auto& [corners, out] : {std::pair{corners_x, t.screen_x}, std::pair{corners_y, t.screen_y}}) {
        transpose(_mm_castsi128_ps(corners[0]), _mm_castsi128_ps(corners[1]), _mm_castsi128_ps(corners[2]),
                  _mm_castsi128_ps(corners[3]), lanes);
        for (int k = 0; k < 3; ++k) out[k] = to_doubles(IntLanes(lanes[k])) * scale;
    }
    transpose(inv_w[0], inv_w[1], inv_w[2], inv_w[3], lanes);
    for (int k = 0; k < 3; ++k) t.inv_w[k] = to_doubles(lanes[k]);
    const DoubleLanes *sx = t.screen_x, *sy = t.screen_y;
    t.area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sy[1] - sy[0]) * (sx[2] - sx[0]);

    // The geometric normal as set_up_triangle computes it (Eigen's cross and norm).
    for (int k = 0; k < 3; ++k) t.position[k] = gather(positions[k]), t.normal[k] = gather(normals[k]);
    t.edge1 = t.position[1] - t.position[0], t.edge2 = t.position[2] - t.position[0];
    const Vector3Lanes across = cross(t.edge1, t.edge2);
    const FloatLanes length = square_root(dot(across, across));
    t.geometric_normal = select(length > 0, across / length, Vector3Lanes{broadcast(0.0f), broadcast(0.0f), broadcast(1.0f)});
    if constexpr (reads_uv) {
        if (!t.any_uv) return;

        for (int k = 0; k < 3; ++k) {  // (u, v) pairs of lanes 0 1 and 2 3, then split
            auto pair = [&](int j) { return load_two(uvs[k][j]->data()); };
            const __m128 low = _mm_movelh_ps(pair(0), pair(1)), high = _mm_movelh_ps(pair(2), pair(3));
            t.u[k] = _mm_shuffle_ps(low, high, _MM_SHUFFLE(2, 0, 2, 0));
            t.v[k] = _mm_shuffle_ps(low, high, _MM_SHUFFLE(3, 1, 3, 1));
            transpose(_mm_loadu_ps(tangents[k][0]->data()), _mm_loadu_ps(tangents[k][1]->data()),
                      _mm_loadu_ps(tangents[k][2]->data()), _mm_loadu_ps(tangents[k][3]->data()), lanes);
            t.tangent[k] = {lanes[0], lanes[1], lanes[2]};
            t.tangent_w[k] = lanes[3];
        }
        // The tangent frame from the uv gradient, for lanes without mesh tangents.
        const FloatLanes d1u = t.u[1] - t.u[0], d1v = t.v[1] - t.v[0], d2u = t.u[2] - t.u[0], d2v = t.v[2] - t.v[0];
        const FloatLanes det = d1u * d2v - d2u * d1v;
        t.has_uv_frame = det != 0;
        t.uv_tangent = (t.edge1 * d2v - t.edge2 * d1v) / det;
        t.uv_bitangent = (t.edge2 * d1u - t.edge1 * d2u) / det;
    }
}

// make_fragment for lane_count visible pixels at x, row y, of the triangles
// `t` (each pixel of its own triangle), with the same operations in lanes
// (renderer/lanes.h).
template <bool reads_uv>
[[gnu::always_inline]] inline FragmentLanes make_fragment_lanes(const TrianglesOf<reads_uv>& t, IntLanes x, int y, int count) {
    FragmentLanes f;
    f.count = count;
    std::copy(t.surface, t.surface + lane_count, f.surface);
    f.has_uv = IntLanes{};
    // Screen barycentrics as screen_barycentrics computes them, then the
    // perspective correction of source_barycentrics, in doubles.
    const DoubleLanes *sx = t.screen_x, *sy = t.screen_y, *w = t.inv_w;
    auto source_barycentrics = [&](const DoubleLanes& px, const DoubleLanes& py, FloatLanes b[3]) {
        const DoubleLanes l0 = ((sx[2] - sx[1]) * (py - sy[1]) - (sy[2] - sy[1]) * (px - sx[1])) / t.area;
        const DoubleLanes l1 = ((sx[0] - sx[2]) * (py - sy[2]) - (sy[0] - sy[2]) * (px - sx[2])) / t.area;
        const DoubleLanes l2 = 1 - l0 - l1;
        const DoubleLanes q0 = l0 * w[0], q1 = l1 * w[1], q2 = l2 * w[2];
        const DoubleLanes sum = q0 + q1 + q2;
        const IntLanes nonzero = not_zero(sum);
        b[0] = select(nonzero, to_floats(q0 / sum), broadcast(1.0f));
        b[1] = select(nonzero, to_floats(q1 / sum), broadcast(0.0f));
        b[2] = select(nonzero, to_floats(q2 / sum), broadcast(0.0f));
        for (int j = 0; j < count; ++j)
            if (t.clipped[j]) {
                Eigen::Vector3f s = source_of_clipped(*t.clipped[j], Eigen::Vector3f(b[0][j], b[1][j], b[2][j]));
                b[0][j] = s[0], b[1][j] = s[1], b[2][j] = s[2];
            }
    };
    const DoubleLanes px = to_doubles(x) + 0.5, py = broadcast(y + 0.5);
    FloatLanes b[3];
    source_barycentrics(px, py, b);

    f.position = t.position[0] * b[0] + t.position[1] * b[1] + t.position[2] * b[2];
    f.geometric_normal = t.geometric_normal;
    const Vector3Lanes normal = t.normal[0] * b[0] + t.normal[1] * b[1] + t.normal[2] * b[2];
    const FloatLanes squared = dot(normal, normal);
    f.normal = select(t.has_normals & (squared > 0), normal / square_root(squared), t.geometric_normal);
    if constexpr (reads_uv) {
        if (!t.any_uv) return f;

        // Uvs, their change one pixel right and down, and the tangent frame, as make_fragment makes them.
        f.has_uv = t.has_uv;
        std::copy(t.uv_gradient_of_lane, t.uv_gradient_of_lane + lane_count, f.uv_gradient);
        auto interpolate = [&](const FloatLanes* values, const FloatLanes* weights) {
            return values[0] * weights[0] + values[1] * weights[1] + values[2] * weights[2];
        };
        FloatLanes right[3], down[3];
        source_barycentrics(px + 1, py, right);
        source_barycentrics(px, broadcast(y + 0.5 + 1), down);
        const FloatLanes zero{};
        f.u = select(t.has_uv, interpolate(t.u, b), zero);
        f.v = select(t.has_uv, interpolate(t.v, b), zero);
        f.du_dx = select(t.has_uv, interpolate(t.u, right) - f.u, zero);
        f.dv_dx = select(t.has_uv, interpolate(t.v, right) - f.v, zero);
        f.du_dy = select(t.has_uv, interpolate(t.u, down) - f.u, zero);
        f.dv_dy = select(t.has_uv, interpolate(t.v, down) - f.v, zero);

        // Mesh tangents interpolated (w gives the bitangent's sign), else the uv frame.
        const Vector3Lanes mesh_tangent = t.tangent[0] * b[0] + t.tangent[1] * b[1] + t.tangent[2] * b[2];
        const FloatLanes mesh_w = interpolate(t.tangent_w, b);
        Vector3Lanes tangent = select(t.has_tangents, mesh_tangent, t.uv_tangent);
        tangent = tangent - f.normal * dot(f.normal, tangent);  // Gram-Schmidt against the shading normal
        const FloatLanes tangent_squared = dot(tangent, tangent);
        tangent = tangent / square_root(tangent_squared);
        const Vector3Lanes across = cross(f.normal, tangent);
        // The bitangent points up the image, against dp/dv (glTF: uv origin at the top left).
        const FloatLanes handedness = select(t.has_tangents, select(mesh_w < 0, broadcast(-1.0f), broadcast(1.0f)),
                                             select(dot(across, t.uv_bitangent) > 0, broadcast(-1.0f), broadcast(1.0f)));
        const IntLanes framed = t.has_uv & (t.has_tangents | t.has_uv_frame) & (tangent_squared > 0);
        f.tangent = select(framed, tangent, Vector3Lanes{broadcast(1.0f), broadcast(0.0f), broadcast(0.0f)});
        f.bitangent = select(framed, across * handedness, Vector3Lanes{broadcast(0.0f), broadcast(1.0f), broadcast(0.0f)});
    }
    return f;
}

// Textured pixels reuse the lanes of their triangles (`t`, gathered again
// where `ids` differ from its own), which pays for large triangles; untextured
// ones gather them each time into a local: in the benchmark's frame of a
// million small triangles, keeping them for reuse made it about 20 % slower
// (docs/performance.md: Lanes).
FragmentLanes make_textured_fragment_lanes(const Context& c, const std::uint32_t ids[lane_count], bool other_triangles,
                                           TexturedTriangleLanes& t, IntLanes x, int y, int count) {
    if (other_triangles) gather_triangles<true>(c, ids, t);
    return make_fragment_lanes<true>(t, x, y, count);
}

FragmentLanes make_untextured_fragment_lanes(const Context& c, const std::uint32_t ids[lane_count], IntLanes x, int y, int count) {
    TriangleLanes t;
    gather_triangles<false>(c, ids, t);
    return make_fragment_lanes<false>(t, x, y, count);
}

// Distance in pixels from a pixel centre to the nearest edge of the source triangle.
float edge_distance(const TriangleSetup& s, int x, int y) {
    Eigen::Vector3d l = screen_barycentrics(s.barycentrics, x + 0.5, y + 0.5);
    Eigen::Vector3d lx = screen_barycentrics(s.barycentrics, x + 1.5, y + 0.5) - l,
                    ly = screen_barycentrics(s.barycentrics, x + 0.5, y + 1.5) - l;
    float nearest = std::numeric_limits<float>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (s.barycentrics.clipped) {  // edges made by clipping are not edges of the model
            const ClippedWeights& w = *s.barycentrics.clipped;
            int a = (k + 1) % 3, b = (k + 2) % 3;
            bool original = false;
            for (int m = 0; m < 3; ++m) original = original || (w.weights[a][m] == 0 && w.weights[b][m] == 0);
            if (!original) continue;
        }
        double gradient = std::hypot(lx[k], ly[k]);
        if (gradient > 0) nearest = std::min(nearest, float(std::abs(l[k]) / gradient));
    }
    return nearest;
}

// The tiles each of the chunk's triangles from `first` on touches (a range
// of columns and rows; empty when it has no pixel), and how many triangles
// each tile gets: run on each block of triangles right after its set-up,
// while they are in cache.
void count_tiles(Chunk& chunk, std::size_t first, const Tiling& tiling, const Viewport& viewport) {
    const std::size_t end = chunk.triangles.size();
    chunk.tiles_of.resize(end);
    // Locals: stores through them cannot make the compiler reload the vectors.
    const ScreenTriangle* const triangles = chunk.triangles.data();
    TileRange* const tiles_of = chunk.tiles_of.data();
    std::uint32_t* const counts = chunk.tile_counts.data();
    for (std::size_t i = first; i < end; ++i) {
        int x0, y0, x1, y1;
        TileRange& tiles = tiles_of[i];
        if (!triangle_pixel_bounds(triangles[i], viewport, x0, y0, x1, y1)) {
            tiles = {1, 0, 0, 0};
            continue;
        }
        // Bounds are >= 0: a shift divides.
        tiles = {x0 >> tile_bits, y0 >> tile_bits, x1 >> tile_bits, y1 >> tile_bits};
        for (int row = tiles.y0; row <= tiles.y1; ++row)
            for (int column = tiles.x0; column <= tiles.x1; ++column) ++counts[row * tiling.columns + column];
    }
}

// Sorts the chunk's triangles into the tiles they touch, as counted by
// count_tiles, so that each tile's bin keeps submission order.
void fill_bins(Chunk& chunk, const Tiling& tiling) {
    chunk.bin_start.assign(tiling.count() + 1, 0);
    for (int tile = 0; tile < tiling.count(); ++tile)
        chunk.bin_start[tile + 1] = chunk.bin_start[tile] + chunk.tile_counts[tile];
    chunk.bin_items.resize(chunk.bin_start.back());
    std::uint32_t* const next = chunk.tile_counts.data();  // from now on each bin's next slot
    std::copy(chunk.bin_start.begin(), chunk.bin_start.end() - 1, next);
    std::uint32_t* const items = chunk.bin_items.data();
    const TileRange* const tiles_of = chunk.tiles_of.data();
    for (std::size_t i = 0; i < chunk.tiles_of.size(); ++i) {
        const TileRange tiles = tiles_of[i];
        for (int row = tiles.y0; row <= tiles.y1; ++row)
            for (int column = tiles.x0; column <= tiles.x1; ++column)
                items[next[row * tiling.columns + column]++] = std::uint32_t(i);
    }
}

// Blended triangles over the resolved tile, back to front by their mean window
// depth (ties by submission): one global order, so every tile and thread count
// composites alike. Each is depth-tested against the opaque surfaces and
// composited source-over (Porter and Duff 1984): c = a c_src + (1 - a) c_dst,
// coverage a + (1 - a) a_dst. Intersecting or cyclic glass is as good as that
// order, as in engines that sort transparent draws.
template <typename Shade>
void composite_blended(const Context& c, std::vector<std::uint32_t>& blended, const TileTarget& opaque, Frame& frame,
                       const Shade& shade) {
    auto mean_depth = [&](std::uint32_t id) {
        const std::vector<ClippedWeights>* weights;
        const ScreenTriangle& t = triangle_of(c, id, weights);
        return t.z[0] + t.z[1] + t.z[2];
    };
    std::sort(blended.begin(), blended.end(), [&](std::uint32_t a, std::uint32_t b) {
        float za = mean_depth(a), zb = mean_depth(b);
        return za != zb ? za > zb : a < b;
    });
    for (std::uint32_t id : blended) {
        TriangleSetup setup;
        set_up_triangle(c, id, setup);
        visit_triangle(*setup.screen, opaque, [&](int x, int y, float depth) {
            ShadedPixel shaded = shade(setup, x, y);
            float a = std::clamp(shaded.alpha, 0.0f, 1.0f);
            std::size_t pixel = std::size_t(y) * frame.width + x;
            Eigen::Vector4f& color = frame.color[pixel];
            color.head<3>() = shaded.color * a + color.head<3>() * (1 - a);
            color.w() += a * (1 - color.w());
            if (depth < frame.depth[pixel]) frame.depth[pixel] = depth, frame.normal[pixel] = shaded.normal;
        });
    }
}

// The tile's shaded pixels (`color`, `normal`, row stride tile.stride) into the
// frame. Unless the tile will read them again (to blend over them), with
// streaming stores, in one pass at the tile's end: a 1080p frame (66 MB) is
// far larger than the caches, an ordinary store first reads the line it
// writes, and streamed stores made one at a time while shading held the
// buffers that texture reads wait for (docs/performance.md: Streaming stores).
void write_tile(const TileTarget& tile, const Eigen::Vector3f* color, const Eigen::Vector3f* normal, bool streaming,
                Frame& frame) {
    auto stream = [](float* to, float value) {
        std::int32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        _mm_stream_si32(reinterpret_cast<int*>(to), bits);
    };
    static_assert(alignof(Eigen::Vector4f) == 16);  // each colour one aligned 16-byte store
    const int width = tile.x1 - tile.x0;
    for (int y = tile.y0; y < tile.y1; ++y) {
        // Row pointers, so the stores cannot make the compiler reload them.
        const std::size_t first = std::size_t(y) * frame.width + tile.x0;
        Eigen::Vector4f* const color_row = frame.color.data() + first;
        float* const depth_row = frame.depth.data() + first;
        Eigen::Vector3f* const normal_row = frame.normal.data() + first;
        const int row = (y - tile.y0) * tile.stride;
        for (int x = 0; x < width; ++x) {
            const int k = row + x;
            if (tile.id[k] == no_triangle) continue;
            if (!streaming) {
                color_row[x] = Eigen::Vector4f(color[k].x(), color[k].y(), color[k].z(), 1);
                depth_row[x] = tile.depth[k];
                normal_row[x] = normal[k];
                continue;
            }
            _mm_stream_ps(color_row[x].data(), _mm_setr_ps(color[k].x(), color[k].y(), color[k].z(), 1.0f));
            stream(depth_row + x, tile.depth[k]);
            for (int i = 0; i < 3; ++i) stream(normal_row[x].data() + i, normal[k][i]);
        }
    }
    _mm_sfence();  // streamed stores are weakly ordered: done before another thread reads the frame
}

// The pixels of tile `tile` within the viewport and its scissor (empty: x0 >= x1 or y0 >= y1).
TileTarget tile_pixels(const Tiling& tiling, int tile, const Viewport& viewport) {
    int x0 = (tile % tiling.columns) * tile_size, y0 = (tile / tiling.columns) * tile_size;
    int x1 = std::min(x0 + tile_size, viewport.width), y1 = std::min(y0 + tile_size, viewport.height);
    x0 = std::max(x0, viewport.scissor_x0), y0 = std::max(y0, viewport.scissor_y0);
    x1 = std::min(x1, viewport.scissor_x1), y1 = std::min(y1, viewport.scissor_y1);
    return {x0, y0, x1, y1, tile_size, nullptr, nullptr};
}

bool has_triangles(const Context& c, int tile) {
    for (std::size_t chunk_index = 0; chunk_index < c.chunk_count; ++chunk_index)
        if (c.chunks[chunk_index].bin_start[tile + 1] > c.chunks[chunk_index].bin_start[tile]) return true;
    return false;
}

// The visibility buffer: depths from infinity (or the frame's, when asked),
// then the opaque and masked triangles in submission order. Returns the
// blended triangles, which are composited after shading.
std::vector<std::uint32_t> find_visible(const Context& c, int tile, const TileTarget& target, const Frame& frame) {
    std::fill(target.depth, target.depth + tile_size * tile_size, std::numeric_limits<float>::infinity());
    if (c.settings.depth_from_frame)
        for (int y = target.y0; y < target.y1; ++y)
            std::copy_n(&frame.depth[std::size_t(y) * std::size_t(frame.width) + std::size_t(target.x0)],
                        target.x1 - target.x0, &target.depth[(y - target.y0) * tile_size]);
    std::fill(target.id, target.id + tile_size * tile_size, no_triangle);
    std::vector<std::uint32_t> blended;
    for (std::size_t chunk_index = 0; chunk_index < c.chunk_count; ++chunk_index) {
        const Chunk& chunk = c.chunks[chunk_index];
        for (std::uint32_t k = chunk.bin_start[tile]; k < chunk.bin_start[tile + 1]; ++k) {
            std::uint32_t i = chunk.bin_items[k];
            const ScreenTriangle& t = chunk.triangles[i];
            std::uint32_t id = std::uint32_t(chunk_index << chunk_index_bits) | i;
            const Batch& batch = c.batches[t.batch];
            const Surface& surface = batch.surface;
            if (surface.alpha_mode == AlphaMode::blend) {
                blended.push_back(id);
                continue;
            }
            bool textured_mask = surface.alpha_mode == AlphaMode::mask && surface.color && !batch.mesh->uvs.empty();
            if (surface.alpha_mode == AlphaMode::mask && !textured_mask && surface.base_color.w() < surface.alpha_cutoff) continue;
            if (!textured_mask) {
                rasterize_triangle(t, id, target, nullptr);
                continue;
            }
            const BarycentricSetup barycentrics = barycentric_setup(t, chunk.weights);
            FragmentTest keep = [&](const ScreenTriangle& tri, int x, int y) {
                const Mesh& mesh = *batch.mesh;
                Eigen::Vector3f b = source_barycentrics(barycentrics, x + 0.5, y + 0.5);
                Eigen::Vector2f uv = interpolate(mesh.uvs, &mesh.indices[std::size_t(tri.triangle) * 3], b);
                return surface.base_color.w() * sample(*surface.color, uv).w() >= surface.alpha_cutoff;
            };
            rasterize_triangle(t, id, target, &keep);
        }
    }
    return blended;
}

// One pixel of a triangle shaded, with the wireframe over it when asked.
ShadedPixel shade_pixel(const Context& c, const TriangleSetup& setup, int x, int y, bool reads_uv) {
    Fragment fragment = make_fragment(setup, x, y, reads_uv);
    ShadedPixel shaded = c.shader.shade(setup.batch->surface, fragment);
    if (c.settings.wireframe && edge_distance(setup, x, y) < 0.75f) shaded.color = c.settings.wireframe_color;
    return shaded;
}

// A tile's shaded colours and normals, row stride tile_size.
struct ShadedTile {
    Eigen::Vector3f color[tile_size * tile_size], normal[tile_size * tile_size];
};

// Every visible pixel shaded one at a time (shaders without lanes).
void shade_each_pixel(const Context& c, const TileTarget& t, ShadedTile& out) {
    const int x0 = t.x0, y0 = t.y0, x1 = t.x1, y1 = t.y1;
    const bool reads_uv = c.shader.reads_uv();
    std::uint32_t setup_id = no_triangle;
    TriangleSetup setup;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const int k = (y - y0) * tile_size + (x - x0);
            std::uint32_t id = t.id[k];
            if (id == no_triangle) continue;
            if (id != setup_id) set_up_triangle(c, id, setup), setup_id = id;
            ShadedPixel shaded = shade_pixel(c, setup, x, y, reads_uv);
            out.color[k] = shaded.color, out.normal[k] = shaded.normal;
        }
}

// lane_count visible pixels of a row at a time. Their x are shifted into
// lanes from the top, in registers: see DoubleLanes (renderer/lanes.h).
// Groups of one triangle's pixels reuse its gathered lanes. (Whether the
// group's triangles changed is noted as ids come: a load of several ids just
// stored would wait for every store before, the frame's too.)
void shade_in_lanes(const Context& c, const TileTarget& t, ShadedTile& out) {
    const int x0 = t.x0, y0 = t.y0, x1 = t.x1, y1 = t.y1;
    const std::uint32_t* const ids = t.id;
    Eigen::Vector3f* const shaded_color = out.color;
    Eigen::Vector3f* const shaded_normal = out.normal;
    const bool reads_uv = c.shader.reads_uv();
    TexturedTriangleLanes triangles;
    std::fill(triangles.ids, triangles.ids + lane_count, no_triangle);
    bool other_triangles = false;
    for (int y = y0; y < y1; ++y) {
        std::uint32_t lanes[lane_count];
        __m128i xs = _mm_setzero_si128();
        int count = 0;
        auto shade_lanes = [&] {
            switch (count) {  // the first pixel into lane 0
            case 1: xs = _mm_srli_si128(xs, 12); break;
            case 2: xs = _mm_srli_si128(xs, 8); break;
            case 3: xs = _mm_srli_si128(xs, 4); break;
            }
            for (int j = count; j < lane_count; ++j) {
                lanes[j] = lanes[count - 1];
                other_triangles = other_triangles || lanes[j] != triangles.ids[j];
            }
            ShadedLanes shaded;
            c.shader.shade_lanes(reads_uv ? make_textured_fragment_lanes(c, lanes, other_triangles, triangles, IntLanes(xs), y, count)
                                          : make_untextured_fragment_lanes(c, lanes, IntLanes(xs), y, count),
                                 shaded);
            other_triangles = false;
            alignas(16) int x[lane_count];
            _mm_store_si128(reinterpret_cast<__m128i*>(x), xs);
            for (int j = 0; j < count; ++j) {
                Eigen::Vector3f color = lane(shaded.color, j);
                if (c.settings.wireframe) {
                    TriangleSetup setup;
                    set_up_triangle(c, lanes[j], setup);
                    if (edge_distance(setup, x[j], y) < 0.75f) color = c.settings.wireframe_color;
                }
                const int k = (y - y0) * tile_size + (x[j] - x0);
                shaded_color[k] = color, shaded_normal[k] = lane(shaded.normal, j);
            }
            count = 0;
        };
        for (int x = x0; x < x1; ++x) {
            std::uint32_t id = ids[(y - y0) * tile_size + (x - x0)];
            if (id == no_triangle) continue;
            other_triangles = other_triangles || id != triangles.ids[count];
            lanes[count++] = id;
            xs = _mm_or_si128(_mm_srli_si128(xs, 4), _mm_slli_si128(_mm_cvtsi32_si128(x), 12));
            if (count == lane_count) shade_lanes();
        }
        if (count > 0) shade_lanes();
    }
}

// One tile, start to end: visibility, shading, the write into the frame,
// and the blended triangles over it. An empty tile (sky, background) writes nothing.
void render_tile(const Context& c, const Tiling& tiling, int tile, Frame& frame, const Viewport& viewport) {
    TileTarget target = tile_pixels(tiling, tile, viewport);
    if (target.x0 >= target.x1 || target.y0 >= target.y1 || !has_triangles(c, tile)) return;
    float depth[tile_size * tile_size];
    std::uint32_t ids[tile_size * tile_size];
    target.depth = depth, target.id = ids;
    std::vector<std::uint32_t> blended = find_visible(c, tile, target, frame);
    ShadedTile shaded;
    if (c.shader.takes_lanes()) shade_in_lanes(c, target, shaded);
    else shade_each_pixel(c, target, shaded);
    write_tile(target, shaded.color, shaded.normal, blended.empty(), frame);
    if (!blended.empty()) {
        const bool reads_uv = c.shader.reads_uv();
        composite_blended(c, blended, target, frame,
                          [&](const TriangleSetup& setup, int x, int y) { return shade_pixel(c, setup, x, y, reads_uv); });
    }
}

}  // namespace

namespace {

// A batch's vertices or triangles [begin, end): the unit of parallel work.
struct Range {
    std::size_t batch, begin, end;
};

Viewport viewport_of(const Frame& frame, const RenderSettings& settings) {
    Viewport viewport;
    viewport.width = frame.width;
    viewport.height = frame.height;
    viewport.scissor_x0 = std::max(0, settings.scissor_x0);
    viewport.scissor_y0 = std::max(0, settings.scissor_y0);
    viewport.scissor_x1 = std::min(frame.width, settings.scissor_x1);
    viewport.scissor_y1 = std::min(frame.height, settings.scissor_y1);
    return viewport;
}

// Vertex stage: clip-space positions, outcodes and snapped window positions,
// in parallel over vertex ranges. Returns the triangle ranges, a chunk each.
std::vector<Range> project_vertices(const std::vector<Batch>& batches, const Eigen::Matrix4f& view_projection,
                                    const Viewport& viewport, int threads,
                                    std::vector<std::vector<ProjectedVertex>>& projected) {
    projected.resize(std::max(projected.size(), batches.size()));
    std::vector<Range> vertex_ranges, triangle_ranges;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        projected[b].resize(batches[b].mesh->positions.size());
        for (std::size_t i = 0; i < projected[b].size(); i += triangles_per_chunk)
            vertex_ranges.push_back({b, i, std::min(projected[b].size(), i + triangles_per_chunk)});
        std::size_t triangles = batches[b].mesh->indices.size() / 3;
        for (std::size_t i = 0; i < triangles; i += triangles_per_chunk)
            triangle_ranges.push_back({b, i, std::min(triangles, i + triangles_per_chunk)});
    }
    parallel_for(vertex_ranges.size(), threads, [&](std::size_t r) {
        const Range& range = vertex_ranges[r];
        const auto& positions = batches[range.batch].mesh->positions;
        for (std::size_t i = range.begin; i < range.end; ++i)
            projected[range.batch][i] = project_vertex(clip_position(view_projection, positions[i]), viewport);
    });
    return triangle_ranges;
}

// Set-up and binning, in parallel over chunks of triangles, each in blocks
// binned while their screen triangles are still in cache.
void bin_triangles(const std::vector<Batch>& batches, const std::vector<Range>& triangle_ranges,
                   const std::vector<std::vector<ProjectedVertex>>& projected, const Eigen::Matrix4f& view_projection,
                   const RenderSettings& settings, const Viewport& viewport, const Tiling& tiling, int threads,
                   std::vector<Chunk>& chunks) {
    if (chunks.size() < triangle_ranges.size()) chunks.resize(triangle_ranges.size());
    for (std::size_t c = 0; c < triangle_ranges.size(); ++c) {
        chunks[c].triangles.clear();
        chunks[c].weights.clear();
    }
    parallel_for(triangle_ranges.size(), threads, [&](std::size_t r) {
        const Range& range = triangle_ranges[r];
        Chunk& chunk = chunks[r];
        const Mesh& mesh = *batches[range.batch].mesh;
        const ProjectedMesh projected_mesh{mesh.indices.data(), projected[range.batch].data(), mesh.positions.data(),
                                           &view_projection};
        chunk.tile_counts.assign(std::size_t(tiling.count()), 0);
        constexpr std::size_t block = 1024;
        for (std::size_t begin = range.begin; begin < range.end; begin += block) {
            const std::size_t first = chunk.triangles.size();
            setup_triangles(projected_mesh, begin, std::min(range.end, begin + block), std::uint32_t(range.batch),
                            settings.culling, viewport, chunk.triangles, chunk.weights);
            count_tiles(chunk, first, tiling, viewport);
        }
        fill_bins(chunk, tiling);
    });
}

// Where shading sees the eye: an orthographic view has parallel view rays,
// so its "eye" lies far back along them.
Eigen::Vector3f shading_eye(const Camera& camera) {
    if (!camera.orthographic) return camera.position;
    Eigen::Vector3f forward = (camera.target - camera.position).normalized();
    return camera.position - forward * 1e6f;
}

}  // namespace

void render(const std::vector<Batch>& batches, const RenderSettings& settings, Frame& frame) {
    const Viewport viewport = viewport_of(frame, settings);
    const int threads = thread_count(settings.threads);
    const Eigen::Matrix4f view_projection =
        projection_matrix(settings.camera, float(frame.width) / float(frame.height)) * view_matrix(settings.camera);
    // Scratch kept per calling thread: a frame of a million triangles needs
    // ~100 MB, and fresh allocations every frame cost more in page faults than
    // the rasterization itself (measured: 1 thread 416 ms -> 256 ms).
    thread_local std::vector<std::vector<ProjectedVertex>> projected;
    thread_local std::vector<Chunk> chunks;
    const std::vector<Range> triangle_ranges = project_vertices(batches, view_projection, viewport, threads, projected);
    const Tiling tiling{(frame.width + tile_size - 1) / tile_size, (frame.height + tile_size - 1) / tile_size};
    bin_triangles(batches, triangle_ranges, projected, view_projection, settings, viewport, tiling, threads, chunks);

    // Tiles: each owned by one thread; triangles replayed in submission order.
    std::unique_ptr<Shader> mode_shader = settings.shader ? nullptr : make_shader(settings, shading_eye(settings.camera));
    Context context{batches, settings, chunks, triangle_ranges.size(), settings.shader ? *settings.shader : *mode_shader};
    parallel_for(std::size_t(tiling.count()), threads,
                 [&](std::size_t tile) { render_tile(context, tiling, int(tile), frame, viewport); });
}

Image8 frame_to_srgb8(const Frame& frame) {
    Image8 image(frame.width, frame.height, 3);
    for (std::size_t i = 0; i < frame.color.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = linear_to_srgb(frame.color[i][c]);
    return image;
}

Image8 coverage_mask(const Frame& frame) {
    Image8 mask(frame.width, frame.height, 1);
    for (std::size_t i = 0; i < frame.color.size(); ++i) mask.pixels[i] = frame.color[i].w() > 0 ? 255 : 0;
    return mask;
}

}  // namespace boxlod
