#include "renderer/fragment_stage.h"

#include "renderer/lanes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace boxlod::pipeline {
namespace {

// The gradients g of u and v in the plane of a triangle with edges e1, e2
// and uv changes d1, d2 along them: g . e1 = d1 and g . e2 = d2, so
// g = [e1 e2] G^-1 d (G the edges' Gram matrix). False for a degenerate
// triangle. Out of line, from the mesh: only metric parallax needs it, and
// inlined its registers would cost every other triangle's setup.
[[gnu::noinline]] bool uv_gradient_of(const Mesh& mesh, const std::uint32_t* v, UvGradient& gradient) {
    const Eigen::Vector3f e1 = mesh.positions[v[1]] - mesh.positions[v[0]],
                          e2 = mesh.positions[v[2]] - mesh.positions[v[0]];
    const Eigen::Vector2f d1 = mesh.uvs[v[1]] - mesh.uvs[v[0]], d2 = mesh.uvs[v[2]] - mesh.uvs[v[0]];
    float a = e1.dot(e1), b = e1.dot(e2), d = e2.dot(e2), det = a * d - b * b;
    if (!(det > 0)) return false;
    gradient.du_dposition = (e1 * (d * d1.x() - b * d2.x()) + e2 * (a * d2.x() - b * d1.x())) / det;
    gradient.dv_dposition = (e1 * (d * d1.y() - b * d2.y()) + e2 * (a * d2.y() - b * d1.y())) / det;
    return true;
}

}  // namespace

void set_up_triangle(const Context& c, std::uint32_t id, TriangleSetup& s) {
    const std::vector<ClippedWeights>* weights;
    s.screen = &triangle_of(c, id, weights);
    s.batch = &c.batches[s.screen->batch];
    const Mesh& mesh = *s.batch->mesh;
    s.v = &mesh.indices[std::size_t(s.screen->triangle) * 3];
    s.barycentrics = barycentric_setup(*s.screen, *weights);
    const Eigen::Vector3f &p0 = mesh.positions[s.v[0]], &p1 = mesh.positions[s.v[1]],
                          &p2 = mesh.positions[s.v[2]];
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
    if (surface.height && surface.height_depth > 0)
        s.has_uv_gradient = uv_gradient_of(mesh, s.v, s.uv_gradient);
}

namespace {

Fragment make_fragment(const TriangleSetup& s, int x, int y, bool reads_uv) {
    const Mesh& mesh = *s.batch->mesh;
    const std::uint32_t* v = s.v;
    double px = x + 0.5, py = y + 0.5;
    Eigen::Vector3f b = source_barycentrics(s.barycentrics, px, py);
    Fragment f;
    f.position = mesh.positions[v[0]] * b[0] + mesh.positions[v[1]] * b[1] + mesh.positions[v[2]] * b[2];
    if (!s.batch->translation.isZero(0)) f.position += s.batch->translation;
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
    Vector3Lanes translation;  // the batches', read only when `translated`
    IntLanes has_normals;
    const Surface* surface[lane_count];
    bool any_uv = false, translated = false;
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
    out[0] = r0;
    out[1] = r1;
    out[2] = r2;
    out[3] = r3;
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

// Per lane, where its triangle's values are, before they are read into lanes.
struct LaneSources {
    __m128i corners_x[lane_count], corners_y[lane_count];
    __m128 inv_w[lane_count];
    const Eigen::Vector3f *positions[3][lane_count], *normals[3][lane_count], *translations[lane_count];
    const Eigen::Vector2f* uvs[3][lane_count];
    const Eigen::Vector4f* tangents[3][lane_count];
};

// Each lane's triangle looked up: its screen corners, its vertices' values
// (zeros where the mesh has none), its surface and uv gradient.
template <bool reads_uv>
[[gnu::always_inline]] inline void find_lane_sources(const Context& c, const std::uint32_t ids[lane_count],
                                                     TrianglesOf<reads_uv>& t, LaneSources& from) {
    static_assert(offsetof(ScreenTriangle, y) == offsetof(ScreenTriangle, x) + 12 &&
                  offsetof(ScreenTriangle, inv_w) + 16 <= sizeof(ScreenTriangle));
    static const Eigen::Vector3f no_normal = Eigen::Vector3f::Zero();
    static const Eigen::Vector2f no_uv = Eigen::Vector2f::Zero();
    static const Eigen::Vector4f no_tangent = Eigen::Vector4f::Zero();
    t.any_uv = t.translated = false;
    for (int j = 0; j < lane_count; ++j) {
        t.ids[j] = ids[j];
        const std::vector<ClippedWeights>* weights;
        const ScreenTriangle& screen = triangle_of(c, ids[j], weights);
        const auto* bytes = reinterpret_cast<const char*>(&screen);
        from.corners_x[j] =
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes + offsetof(ScreenTriangle, x)));
        from.corners_y[j] =
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes + offsetof(ScreenTriangle, y)));
        from.inv_w[j] = _mm_loadu_ps(reinterpret_cast<const float*>(bytes + offsetof(ScreenTriangle, inv_w)));
        t.clipped[j] = screen.clipped >= 0 ? &(*weights)[std::size_t(screen.clipped)] : nullptr;
        const Batch& batch = c.batches[screen.batch];
        const Mesh& mesh = *batch.mesh;
        const std::uint32_t* v = &mesh.indices[std::size_t(screen.triangle) * 3];
        t.has_normals[j] = mesh.normals.empty() ? 0 : -1;
        if (c.translated) {
            from.translations[j] = &batch.translation;
            t.translated = t.translated || !batch.translation.isZero(0);
        }
        for (int k = 0; k < 3; ++k) {
            from.positions[k][j] = &mesh.positions[v[k]];
            from.normals[k][j] = mesh.normals.empty() ? &no_normal : &mesh.normals[v[k]];
        }
        t.surface[j] = &batch.surface;
        if constexpr (reads_uv) {
            const bool with_uv = !mesh.uvs.empty(), with_tangents = with_uv && !mesh.tangents.empty();
            t.any_uv = t.any_uv || with_uv;
            t.has_uv[j] = with_uv ? -1 : 0;
            t.has_tangents[j] = with_tangents ? -1 : 0;
            for (int k = 0; k < 3; ++k) {
                from.uvs[k][j] = with_uv ? &mesh.uvs[v[k]] : &no_uv;
                from.tangents[k][j] = with_tangents ? &mesh.tangents[v[k]] : &no_tangent;
            }
            const Surface& surface = batch.surface;
            t.uv_gradient_of_lane[j] = nullptr;
            if (!with_uv || !surface.height || !(surface.height_depth > 0)) continue;
            if (j > 0 && ids[j] == ids[j - 1])
                t.uv_gradient_of_lane[j] = t.uv_gradient_of_lane[j - 1];
            else if (uv_gradient_of(mesh, v, t.uv_gradient[j]))
                t.uv_gradient_of_lane[j] = &t.uv_gradient[j];
        }
    }
}

// The screen corners, 1/w and doubled area in lanes; the positions, normals
// and the geometric normal as set_up_triangle computes it (Eigen's cross and norm).
[[gnu::always_inline]] inline void read_position_lanes(const LaneSources& from, TriangleLanes& t) {
    FloatLanes lanes[4];
    const double scale = 1.0 / (1 << subpixel_bits);
    for (const auto& [corners, out] :
         {std::pair{from.corners_x, t.screen_x}, std::pair{from.corners_y, t.screen_y}}) {
        transpose(_mm_castsi128_ps(corners[0]), _mm_castsi128_ps(corners[1]), _mm_castsi128_ps(corners[2]),
                  _mm_castsi128_ps(corners[3]), lanes);
        for (int k = 0; k < 3; ++k) out[k] = to_doubles(IntLanes(lanes[k])) * scale;
    }
    transpose(from.inv_w[0], from.inv_w[1], from.inv_w[2], from.inv_w[3], lanes);
    for (int k = 0; k < 3; ++k) t.inv_w[k] = to_doubles(lanes[k]);
    const DoubleLanes *sx = t.screen_x, *sy = t.screen_y;
    t.area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sy[1] - sy[0]) * (sx[2] - sx[0]);

    for (int k = 0; k < 3; ++k) {
        t.position[k] = gather(from.positions[k]);
        t.normal[k] = gather(from.normals[k]);
    }
    if (t.translated) t.translation = gather(from.translations);
    t.edge1 = t.position[1] - t.position[0];
    t.edge2 = t.position[2] - t.position[0];
    const Vector3Lanes across = cross(t.edge1, t.edge2);
    const FloatLanes length = square_root(dot(across, across));
    t.geometric_normal =
        select(length > 0, across / length, Vector3Lanes{broadcast(0.0f), broadcast(0.0f), broadcast(1.0f)});
}

// The uvs and mesh tangents in lanes, and the tangent frame from the uv
// gradient for lanes without mesh tangents.
[[gnu::always_inline]] inline void read_uv_lanes(const LaneSources& from, TexturedTriangleLanes& t) {
    FloatLanes lanes[4];
    for (int k = 0; k < 3; ++k) {  // (u, v) pairs of lanes 0 1 and 2 3, then split
        auto pair = [&](int j) { return load_two(from.uvs[k][j]->data()); };
        const __m128 low = _mm_movelh_ps(pair(0), pair(1)), high = _mm_movelh_ps(pair(2), pair(3));
        t.u[k] = _mm_shuffle_ps(low, high, _MM_SHUFFLE(2, 0, 2, 0));
        t.v[k] = _mm_shuffle_ps(low, high, _MM_SHUFFLE(3, 1, 3, 1));
        transpose(_mm_loadu_ps(from.tangents[k][0]->data()), _mm_loadu_ps(from.tangents[k][1]->data()),
                  _mm_loadu_ps(from.tangents[k][2]->data()), _mm_loadu_ps(from.tangents[k][3]->data()),
                  lanes);
        t.tangent[k] = {lanes[0], lanes[1], lanes[2]};
        t.tangent_w[k] = lanes[3];
    }
    const FloatLanes d1u = t.u[1] - t.u[0], d1v = t.v[1] - t.v[0], d2u = t.u[2] - t.u[0],
                     d2v = t.v[2] - t.v[0];
    const FloatLanes det = d1u * d2v - d2u * d1v;
    t.has_uv_frame = det != 0;
    t.uv_tangent = (t.edge1 * d2v - t.edge2 * d1v) / det;
    t.uv_bitangent = (t.edge2 * d1u - t.edge1 * d2u) / det;
}

// What make_fragment_lanes reads of the triangles `ids`, in lanes.
template <bool reads_uv>
[[gnu::always_inline]] inline void gather_triangles(const Context& c, const std::uint32_t ids[lane_count],
                                                    TrianglesOf<reads_uv>& t) {
    LaneSources from;
    find_lane_sources<reads_uv>(c, ids, t, from);
    read_position_lanes(from, t);
    if constexpr (reads_uv)
        if (t.any_uv) read_uv_lanes(from, t);
}

// The source barycentrics of lane_count pixels at (px, py): screen
// barycentrics as screen_barycentrics computes them, then the perspective
// correction of source_barycentrics, in doubles; clipped lanes mapped to their
// source triangle.
[[gnu::always_inline]] inline void source_barycentric_lanes(const TriangleLanes& t, const DoubleLanes& px,
                                                            const DoubleLanes& py, int count,
                                                            FloatLanes b[3]) {
    const DoubleLanes *sx = t.screen_x, *sy = t.screen_y, *w = t.inv_w;
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
            b[0][j] = s[0];
            b[1][j] = s[1];
            b[2][j] = s[2];
        }
}

// Uvs, their change one pixel right and down, and the tangent frame, as
// make_fragment makes them, for the pixels at (px, py) of barycentrics b.
[[gnu::always_inline]] inline void add_uv_lanes(const TexturedTriangleLanes& t, const DoubleLanes& px,
                                                const DoubleLanes& py, const FloatLanes b[3], int count,
                                                FragmentLanes& f) {
    f.has_uv = t.has_uv;
    std::copy(t.uv_gradient_of_lane, t.uv_gradient_of_lane + lane_count, f.uv_gradient);
    auto interpolate = [&](const FloatLanes* values, const FloatLanes* weights) {
        return values[0] * weights[0] + values[1] * weights[1] + values[2] * weights[2];
    };
    FloatLanes right[3], down[3];
    source_barycentric_lanes(t, px + 1, py, count, right);
    source_barycentric_lanes(t, px, py + 1, count, down);
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
    const FloatLanes handedness =
        select(t.has_tangents, select(mesh_w < 0, broadcast(-1.0f), broadcast(1.0f)),
               select(dot(across, t.uv_bitangent) > 0, broadcast(-1.0f), broadcast(1.0f)));
    const IntLanes framed = t.has_uv & (t.has_tangents | t.has_uv_frame) & (tangent_squared > 0);
    f.tangent = select(framed, tangent, Vector3Lanes{broadcast(1.0f), broadcast(0.0f), broadcast(0.0f)});
    f.bitangent =
        select(framed, across * handedness, Vector3Lanes{broadcast(0.0f), broadcast(1.0f), broadcast(0.0f)});
}

// make_fragment for lane_count visible pixels at x, row y, of the triangles
// `t` (each pixel of its own triangle), with the same operations in lanes
// (renderer/lanes.h).
template <bool reads_uv>
[[gnu::always_inline]] inline FragmentLanes make_fragment_lanes(const TrianglesOf<reads_uv>& t, IntLanes x,
                                                                int y, int count) {
    FragmentLanes f;
    f.count = count;
    std::copy(t.surface, t.surface + lane_count, f.surface);
    f.has_uv = IntLanes{};
    const DoubleLanes px = to_doubles(x) + 0.5, py = broadcast(y + 0.5);
    FloatLanes b[3];
    source_barycentric_lanes(t, px, py, count, b);

    f.position = t.position[0] * b[0] + t.position[1] * b[1] + t.position[2] * b[2];
    if (t.translated) f.position = f.position + t.translation;
    f.geometric_normal = t.geometric_normal;
    const Vector3Lanes normal = t.normal[0] * b[0] + t.normal[1] * b[1] + t.normal[2] * b[2];
    const FloatLanes squared = dot(normal, normal);
    f.normal = select(t.has_normals & (squared > 0), normal / square_root(squared), t.geometric_normal);
    if constexpr (reads_uv)
        if (t.any_uv) add_uv_lanes(t, px, py, b, count, f);
    return f;
}

// Textured pixels reuse the lanes of their triangles (`t`, gathered again
// where `ids` differ from its own), which pays for large triangles; untextured
// ones gather them each time into a local: in the benchmark's frame of a
// million small triangles, keeping them for reuse made it slower
// (docs/performance.md: Lanes).
FragmentLanes make_textured_fragment_lanes(const Context& c, const std::uint32_t ids[lane_count],
                                           bool other_triangles, TexturedTriangleLanes& t, IntLanes x, int y,
                                           int count) {
    if (other_triangles) gather_triangles<true>(c, ids, t);
    return make_fragment_lanes<true>(t, x, y, count);
}

FragmentLanes make_untextured_fragment_lanes(const Context& c, const std::uint32_t ids[lane_count],
                                             IntLanes x, int y, int count) {
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

}  // namespace

ShadedPixel shade_pixel(const Context& c, const TriangleSetup& setup, int x, int y, bool reads_uv) {
    Fragment fragment = make_fragment(setup, x, y, reads_uv);
    ShadedPixel shaded = c.shader.shade(setup.batch->surface, fragment);
    if (c.settings.wireframe && edge_distance(setup, x, y) < 0.75f) shaded.color = c.settings.wireframe_color;
    return shaded;
}

namespace {

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
            if (id != setup_id) {
                set_up_triangle(c, id, setup);
                setup_id = id;
            }
            ShadedPixel shaded = shade_pixel(c, setup, x, y, reads_uv);
            out.color[k] = shaded.color;
            out.normal[k] = shaded.normal;
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
            c.shader.shade_lanes(reads_uv ? make_textured_fragment_lanes(c, lanes, other_triangles, triangles,
                                                                         IntLanes(xs), y, count)
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
                shaded_color[k] = color;
                shaded_normal[k] = lane(shaded.normal, j);
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

}  // namespace

void shade_tile(const Context& c, const TileTarget& tile, ShadedTile& out) {
    if (c.shader.takes_lanes())
        shade_in_lanes(c, tile, out);
    else
        shade_each_pixel(c, tile, out);
}

}  // namespace boxlod::pipeline
