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

std::int64_t edge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t px, std::int64_t py) {
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

// Appends the triangle of three snapped corners unless it has no area or faces the culled way.
bool append_triangle(const ProjectedVertex& a, const ProjectedVertex& b, const ProjectedVertex& c, std::uint32_t batch,
                     std::uint32_t triangle, Culling culling, std::vector<ScreenTriangle>& out) {
    ScreenTriangle t;
    const ProjectedVertex* corner[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i)
        t.x[i] = corner[i]->x, t.y[i] = corner[i]->y, t.z[i] = corner[i]->z, t.inv_w[i] = corner[i]->inv_w;
    std::int64_t area = doubled_area(t);
    if (area == 0) return false;
    // Counter-clockwise in NDC (y up) is negative area in window space (y down).
    bool front = area < 0;
    if ((culling == Culling::back && !front) || (culling == Culling::front && front)) return false;
    t.batch = batch;
    t.triangle = triangle;
    out.push_back(t);
    return true;
}

}  // namespace

ProjectedVertex project_vertex(const Eigen::Vector4f& clip, const Viewport& viewport) {
    ProjectedVertex v;
    v.clip = clip;
    for (int plane = 0; plane < 6; ++plane)
        if (!(plane_distance(clip, plane) >= 0)) v.outcode |= 1 << plane;  // NaN counts as outside
    if (v.outcode == 0) snap(clip, viewport, v);
    return v;
}

void setup_triangle(const ProjectedVertex* corner[3], std::uint32_t batch, std::uint32_t triangle, Culling culling,
                    const Viewport& viewport, std::vector<ScreenTriangle>& out, std::vector<ClippedWeights>& weights) {
    const int outside_all = corner[0]->outcode & corner[1]->outcode & corner[2]->outcode;
    const int outside_any = corner[0]->outcode | corner[1]->outcode | corner[2]->outcode;
    if (outside_all) return;
    // Inside every plane (nearly every triangle): the corners as the vertex stage snapped them.
    if (!outside_any) {
        append_triangle(*corner[0], *corner[1], *corner[2], batch, triangle, culling, out);
        return;
    }

    ClipVertex buffers[2][max_polygon];
    ClipVertex* polygon = buffers[0];
    int count = 3;
    for (int i = 0; i < 3; ++i) polygon[i] = {corner[i]->clip, Eigen::Vector3f::Unit(i)};
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
        if (!append_triangle(snapped[0], snapped[k], snapped[k + 1], batch, triangle, culling, out)) continue;
        out.back().clipped = std::int32_t(weights.size());
        weights.push_back({{polygon[0].weights, polygon[k].weights, polygon[k + 1].weights}});
    }
}

void setup_triangle(const Eigen::Vector4f clip[3], std::uint32_t batch, std::uint32_t triangle, Culling culling,
                    const Viewport& viewport, std::vector<ScreenTriangle>& out, std::vector<ClippedWeights>& weights) {
    const ProjectedVertex projected[3] = {project_vertex(clip[0], viewport), project_vertex(clip[1], viewport),
                                          project_vertex(clip[2], viewport)};
    const ProjectedVertex* corners[3] = {&projected[0], &projected[1], &projected[2]};
    setup_triangle(corners, batch, triangle, culling, viewport, out, weights);
}

namespace {
// The set-up without the clipped triangle's weights (screen barycentrics need none).
BarycentricSetup screen_setup(const ScreenTriangle& t) {
    const double s = 1.0 / (1 << subpixel_bits);
    BarycentricSetup b;
    b.x0 = t.x[0] * s, b.y0 = t.y[0] * s, b.x1 = t.x[1] * s, b.y1 = t.y[1] * s, b.x2 = t.x[2] * s, b.y2 = t.y[2] * s;
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

Eigen::Vector3f source_barycentrics(const ScreenTriangle& t, const std::vector<ClippedWeights>& weights, double px,
                                    double py) {
    return source_barycentrics(barycentric_setup(t, weights), px, py);
}

bool triangle_pixel_bounds(const ScreenTriangle& t, const Viewport& viewport, int& x0, int& y0, int& x1, int& y1) {
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

namespace {

// Walks the pixels of `t` in the tile that the fill rule gives it and that pass
// depth LESS; `on_pixel(x, y, depth, depth_slot, id_slot)` decides what to write.
template <typename OnPixel>
void walk_triangle(const ScreenTriangle& t, const TileTarget& tile, OnPixel&& on_pixel) {
    // Orient to positive area; vertex o[i] of the stored triangle is corner i here.
    std::int64_t area = doubled_area(t);
    int o[3] = {0, 1, 2};
    if (area < 0) std::swap(o[1], o[2]), area = -area;
    const std::int64_t X[3] = {t.x[o[0]], t.x[o[1]], t.x[o[2]]}, Y[3] = {t.y[o[0]], t.y[o[1]], t.y[o[2]]};
    const double Z[3] = {t.z[o[0]], t.z[o[1]], t.z[o[2]]};

    const std::int32_t half = 1 << (subpixel_bits - 1), one = 1 << subpixel_bits;
    std::int64_t min_x = std::min({X[0], X[1], X[2]}), max_x = std::max({X[0], X[1], X[2]});
    std::int64_t min_y = std::min({Y[0], Y[1], Y[2]}), max_y = std::max({Y[0], Y[1], Y[2]});
    int x0 = std::max<int>(int((min_x - half + one - 1) >> subpixel_bits), tile.x0);
    int y0 = std::max<int>(int((min_y - half + one - 1) >> subpixel_bits), tile.y0);
    int x1 = std::min<int>(int((max_x - half) >> subpixel_bits), tile.x1 - 1);
    int y1 = std::min<int>(int((max_y - half) >> subpixel_bits), tile.y1 - 1);
    if (x0 > x1 || y0 > y1) return;

    // Edge k runs from corner k+1 to corner k+2 (opposite corner k); inside is E >= 0.
    std::int64_t step_x[3], step_y[3], row[3], bias[3];
    const std::int64_t px = std::int64_t(x0) * one + half, py = std::int64_t(y0) * one + half;
    for (int k = 0; k < 3; ++k) {
        int a = (k + 1) % 3, b = (k + 2) % 3;
        std::int64_t dx = X[b] - X[a], dy = Y[b] - Y[a];
        // Top-left rule (y down): a left edge has dy < 0, a top edge dy == 0 and dx > 0.
        bool top_left = dy < 0 || (dy == 0 && dx > 0);
        bias[k] = top_left ? 0 : 1;  // E >= 0 becomes E > 0 off the top and left edges
        row[k] = edge(X[a], Y[a], X[b], Y[b], px, py) - bias[k];
        step_x[k] = -dy * one;
        step_y[k] = dx * one;
    }
    const double inv_area = 1.0 / double(area);
    // Whether a run of n + 1 centres from edge values e keeps every |E| below 2^50
    // (E is linear along the run, so its ends bound it).
    auto exact_in_doubles = [&](std::int64_t e0, std::int64_t e1, std::int64_t e2, std::int64_t n) {
        const std::int64_t limit = std::int64_t(1) << 50;
        const std::int64_t e[3] = {e0, e1, e2};
        for (int k = 0; k < 3; ++k) {
            const std::int64_t a = e[k] + bias[k], b = a + n * step_x[k];
            if (a <= -limit || a >= limit || b <= -limit || b >= limit) return false;
        }
        return true;
    };
    auto shade_pixel = [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2, float* depth,
                           std::uint32_t* ids) {
        // Depth straight from the exact edge values: the same at a pixel however the screen is split.
        double z = (double(e0 + bias[0]) * Z[0] + double(e1 + bias[1]) * Z[1] + double(e2 + bias[2]) * Z[2]) * inv_area;
        float zf = float(z);
        int i = x - tile.x0;
        if (zf < depth[i]) on_pixel(x, y, zf, depth[i], ids[i]);
    };
    // Triangles 8 or more pixels wide: each row's run of inside pixels solved from
    // the edge equations, E(x) = E(x0) + (x - x0) step_x >= 0 (exact integers,
    // so the same pixels as testing each centre). The division that solves it
    // is carried from row to row: with m = |step_x|, E(x0) = f m + r, 0 <= r < m,
    // and a row down adds step_y = fb m + rb. Narrower ones test each pixel.
    if (x1 - x0 >= 7) {
        std::int64_t f[3], r[3], m[3], fb[3], rb[3];
        auto floor_divide = [](std::int64_t a, std::int64_t b, std::int64_t& quotient, std::int64_t& remainder) {
            quotient = a / b;
            if (a % b != 0 && a < 0) --quotient;
            remainder = a - quotient * b;
        };
        for (int k = 0; k < 3; ++k) {
            m[k] = step_x[k] < 0 ? -step_x[k] : step_x[k];
            if (m[k] == 0) continue;
            floor_divide(row[k], m[k], f[k], r[k]);
            floor_divide(step_y[k], m[k], fb[k], rb[k]);
        }
        for (int y = y0; y <= y1; ++y) {
            std::int64_t first = x0, last = x1;
            for (int k = 0; k < 3; ++k) {
                if (step_x[k] > 0) first = std::max(first, std::int64_t(x0) - std::min<std::int64_t>(f[k], 0));
                else if (step_x[k] < 0) last = std::min(last, std::int64_t(x0) + f[k]);
                else if (row[k] < 0) last = x0 - 1;
            }
            if (first <= last) {
                const std::int64_t offset = first - x0;
                std::int64_t e0 = row[0] + offset * step_x[0], e1 = row[1] + offset * step_x[1], e2 = row[2] + offset * step_x[2];
                float* depth = tile.depth + std::size_t(y - tile.y0) * tile.stride;
                std::uint32_t* ids = tile.id + std::size_t(y - tile.y0) * tile.stride;
                int x = int(first);
                if (last - first >= 3 && exact_in_doubles(e0, e1, e2, last - first)) {
                    // Four centres at once: while |E| < 2^50 every E + n step_x is an exact
                    // double, so adding steps in doubles gives shade_pixel's double(E) and depth.
                    auto lanes = [](std::int64_t e, std::int64_t step, std::int64_t bias_k) {
                        const double d = double(e + bias_k), s = double(step);
                        return DoubleLanes{_mm_setr_pd(d, d + s), _mm_setr_pd(d + 2 * s, d + 3 * s)};
                    };
                    DoubleLanes d0 = lanes(e0, step_x[0], bias[0]), d1 = lanes(e1, step_x[1], bias[1]),
                                d2 = lanes(e2, step_x[2], bias[2]);
                    const DoubleLanes s0 = broadcast(double(4 * step_x[0])), s1 = broadcast(double(4 * step_x[1])),
                                      s2 = broadcast(double(4 * step_x[2]));
                    for (; x + 3 <= int(last); x += 4) {
                        const FloatLanes z = to_floats((d0 * Z[0] + d1 * Z[1] + d2 * Z[2]) * inv_area);
                        const int i = x - tile.x0;
                        int passed = _mm_movemask_ps(_mm_cmplt_ps(z, _mm_loadu_ps(depth + i)));
                        for (; passed; passed &= passed - 1) {
                            const int j = __builtin_ctz(unsigned(passed));
                            on_pixel(x + j, y, z[j], depth[i + j], ids[i + j]);
                        }
                        d0 = d0 + s0, d1 = d1 + s1, d2 = d2 + s2;
                    }
                    const std::int64_t done = x - first;
                    e0 += done * step_x[0], e1 += done * step_x[1], e2 += done * step_x[2];
                }
                for (; x <= int(last); ++x) {
                    shade_pixel(x, y, e0, e1, e2, depth, ids);
                    e0 += step_x[0], e1 += step_x[1], e2 += step_x[2];
                }
            }
            for (int k = 0; k < 3; ++k) {
                row[k] += step_y[k];
                if (m[k] == 0) continue;
                f[k] += fb[k], r[k] += rb[k];
                if (r[k] >= m[k]) r[k] -= m[k], ++f[k];
            }
        }
        return;
    }
    for (int y = y0; y <= y1; ++y) {
        std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        float* depth = tile.depth + std::size_t(y - tile.y0) * tile.stride;
        std::uint32_t* ids = tile.id + std::size_t(y - tile.y0) * tile.stride;
        for (int x = x0; x <= x1; ++x) {
            if ((e0 | e1 | e2) >= 0) shade_pixel(x, y, e0, e1, e2, depth, ids);
            e0 += step_x[0], e1 += step_x[1], e2 += step_x[2];
        }
        row[0] += step_y[0], row[1] += step_y[1], row[2] += step_y[2];
    }
}

}  // namespace

void rasterize_triangle(const ScreenTriangle& t, std::uint32_t id, const TileTarget& tile, const FragmentTest* keep) {
    walk_triangle(t, tile, [&](int x, int y, float depth, float& depth_slot, std::uint32_t& id_slot) {
        if (keep && !(*keep)(t, x, y)) return;
        depth_slot = depth;
        id_slot = id;
    });
}

void visit_triangle(const ScreenTriangle& t, const TileTarget& tile, const PixelVisit& visit) {
    walk_triangle(t, tile, [&](int x, int y, float depth, float&, std::uint32_t&) { visit(x, y, depth); });
}

}  // namespace boxlod
