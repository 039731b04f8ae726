#include "toolkit/metrics/flip.h"

#include "base/parallel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace boxlod {

namespace {

using Vector3 = Eigen::Vector3d;

// Linear sRGB (IEC 61966-2-1 primaries, D65 white) to CIE XYZ, Y of white = 1
// (B. Lindbloom, "RGB/XYZ Matrices", sRGB).
const Eigen::Matrix3d& rgb_to_xyz() {
    static const Eigen::Matrix3d m = (Eigen::Matrix3d() << 0.4124564, 0.3575761, 0.1804375,  //
                                      0.2126729, 0.7151522, 0.0721750,                       //
                                      0.0193339, 0.1191920, 0.9503041)
                                         .finished();
    return m;
}
const Eigen::Matrix3d& xyz_to_rgb() {
    static const Eigen::Matrix3d m = rgb_to_xyz().inverse();
    return m;
}
// The reference white: XYZ of linear RGB (1, 1, 1), so white has a* = b* = 0.
const Vector3& white() {
    static const Vector3 w = rgb_to_xyz() * Vector3(1, 1, 1);
    return w;
}

// YyCxCz, the linearized CIELAB opponent space the FLIP paper filters in
// (Kolpatzik and Bouman 1992; Zhang and Wandell's S-CIELAB): CIELAB with the
// cube root replaced by the identity.
Vector3 xyz_to_ycxcz(const Vector3& xyz) {
    Vector3 n = xyz.cwiseQuotient(white());
    return {116 * n.y() - 16, 500 * (n.x() - n.y()), 200 * (n.y() - n.z())};
}
Vector3 ycxcz_to_xyz(const Vector3& ycxcz) {
    double y = (ycxcz.x() + 16) / 116;
    return Vector3(y + ycxcz.y() / 500, y, y - ycxcz.z() / 200).cwiseProduct(white());
}

// The cube root of t > 0: a first guess from the bits (the exponent divided
// by three, error a few percent) and three Halley steps, each tripling the
// correct digits (relative error below 1e-15 on FLIP's range). Twice as fast
// as std::cbrt, which was a tenth of FLIP's time.
double cube_root(double t) {
    double r = std::bit_cast<double>(std::bit_cast<std::uint64_t>(t) / 3 + 0x2A9F7893782DA1CEull);
    for (int i = 0; i < 3; ++i) {
        double r3 = r * r * r;
        r = r * (r3 + 2 * t) / (2 * r3 + t);
    }
    return r;
}

// CIE 1976 L*a*b* (CIE 15:2004, 8.2.1) with exact thresholds (6/29)^3.
Vector3 xyz_to_lab(const Vector3& xyz) {
    constexpr double delta = 6.0 / 29.0;
    auto f = [&](double t) {
        return t > delta * delta * delta ? cube_root(t) : t / (3 * delta * delta) + 4.0 / 29.0;
    };
    Vector3 n = xyz.cwiseQuotient(white());
    double fx = f(n.x()), fy = f(n.y()), fz = f(n.z());
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

// Hunt effect (FLIP, colour pipeline): chroma shrinks with lightness.
Vector3 hunt_adjust(const Vector3& lab) {
    return {lab.x(), 0.01 * lab.x() * lab.y(), 0.01 * lab.x() * lab.z()};
}

// HyAB (Abasi, Tehran, Fairchild 2020): city-block in L*, Euclidean in a*b*.
double hyab(const Vector3& p, const Vector3& q) {
    double da = p.y() - q.y(), db = p.z() - q.z();
    return std::abs(p.x() - q.x()) + std::sqrt(da * da + db * db);
}

Vector3 linear_rgb_to_hunt_lab(const Vector3& rgb) { return hunt_adjust(xyz_to_lab(rgb_to_xyz() * rgb)); }

// FLIP's constants.
constexpr double qc = 0.7, pc = 0.4, pt = 0.95;  // colour error exponent and its redistribution
constexpr double qf = 0.5;                       // feature error exponent
constexpr double feature_width = 0.082;          // degrees, peak to trough of the edge detector

// The largest colour distance, between linear-RGB green and blue, raised to qc.
double max_color_distance() {
    static const double cmax =
        std::pow(hyab(linear_rgb_to_hunt_lab({0, 1, 0}), linear_rgb_to_hunt_lab({0, 0, 1})), qc);
    return cmax;
}

// Contrast sensitivity of one YyCxCz channel in the spatial domain (FLIP,
// colour pipeline): a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + a2 sqrt(pi/b2)
// exp(-pi^2 x^2/b2), x in degrees. Each term is a Gaussian of standard
// deviation sqrt(b / (2 pi^2)) degrees, so the 2D filter is a weighted sum
// of separable Gaussians.
struct Csf {
    double a1, b1, a2, b2;
};
constexpr std::array<Csf, 3> csf = {{
    {1, 0.0047, 0, 1e-5},       // achromatic (Yy)
    {1, 0.0053, 0, 1e-5},       // red-green (Cx)
    {34.1, 0.04, 13.5, 0.025},  // blue-yellow (Cz)
}};

struct WeightedKernel {
    double weight;
    SeparableKernel kernel;
};

// The paper evaluates every channel's filter on one square of radius
// ceil(3 sqrt(b_max / (2 pi^2)) ppd) pixels and scales the 2D weights to sum 1.
std::vector<WeightedKernel> csf_kernels(const Csf& c, double ppd) {
    constexpr double pi = std::numbers::pi;
    double b_max = 0;
    for (const Csf& any : csf) b_max = std::max({b_max, any.b1, any.b2});
    const int radius = int(std::ceil(3 * std::sqrt(b_max / (2 * pi * pi)) * ppd));
    std::vector<WeightedKernel> terms;
    double total = 0;
    for (auto [a, b] : {std::pair{c.a1, c.b1}, std::pair{c.a2, c.b2}}) {
        if (a == 0) continue;
        double sigma = std::sqrt(b / (2 * pi * pi)) * ppd;  // in pixels
        double row_sum = 0;
        for (int i = -radius; i <= radius; ++i) row_sum += std::exp(-0.5 * double(i) * i / (sigma * sigma));
        // This term's share of the unnormalized 2D sum: a sqrt(pi/b) (row sum)^2.
        double mass = a * std::sqrt(pi / b) * row_sum * row_sum;
        std::vector<double> taps = sampled_gaussian(sigma, radius);
        terms.push_back({mass, {taps, taps}});
        total += mass;
    }
    for (WeightedKernel& t : terms) t.weight /= total;
    return terms;
}

// Edge (first derivative) or point (second derivative) detector along x,
// with a Gaussian along y (FLIP, feature pipeline); the 2D kernel's positive
// weights sum to 1 and its negative weights to -1. The sign of every weight
// depends on x alone, so that normalization keeps the kernel separable.
SeparableKernel feature_kernel(double ppd, bool point, bool along_x) {
    const double sigma = 0.5 * feature_width * ppd;
    const int radius = int(std::ceil(3 * sigma));
    std::vector<double> derivative;
    double positive = 0, negative = 0;
    for (int i = -radius; i <= radius; ++i) {
        double g = std::exp(-0.5 * double(i) * i / (sigma * sigma));
        double v = point ? (double(i) * i / (sigma * sigma) - 1) * g : -double(i) * g;
        derivative.push_back(v);
        (v > 0 ? positive : negative) += std::abs(v);
    }
    for (double& v : derivative) v /= v > 0 ? positive : negative;
    std::vector<double> gaussian = sampled_gaussian(sigma, radius);
    return along_x ? SeparableKernel{derivative, gaussian} : SeparableKernel{gaussian, derivative};
}

struct Opponent {
    std::array<Plane, 3> channels;  // Yy, Cx, Cz
};

Opponent to_ycxcz(const Image8& image, int threads) {
    Opponent out;
    for (Plane& p : out.channels) p = Plane(image.width, image.height, 1);
    parallel_for(std::size_t(image.height), threads, [&](std::size_t row) {
        int y = int(row);
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            Vector3 rgb(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]));
            Vector3 v = xyz_to_ycxcz(rgb_to_xyz() * rgb);
            for (int c = 0; c < 3; ++c) *out.channels[c].at(x, y) = v[c];
        }
    });
    return out;
}

struct Kernels {
    std::array<std::vector<WeightedKernel>, 3> csf;  // per YyCxCz channel
    SeparableKernel edge_x, edge_y, point_x, point_y;
};

Kernels flip_kernels(double ppd) {
    if (!(ppd > 0) || !std::isfinite(ppd))
        throw std::invalid_argument("flip: pixels per degree must be positive");
    Kernels kernels;
    for (int c = 0; c < 3; ++c) kernels.csf[c] = csf_kernels(csf[c], ppd);
    kernels.edge_x = feature_kernel(ppd, false, true);
    kernels.edge_y = feature_kernel(ppd, false, false);
    kernels.point_x = feature_kernel(ppd, true, true);
    kernels.point_y = feature_kernel(ppd, true, false);
    return kernels;
}

// One row of one image through both pipelines: Hunt-adjusted L*a*b* of the
// CSF-filtered image, and the edge and point magnitudes of Y / Yn. Reused
// across rows by one thread (fresh vectors per row cost more than the filters).
struct PerceivedRow {
    std::vector<double> lab[3], edges, points;
    std::vector<double> scratch, term_row, gx, gy;
};

// Columns [x_begin, x_end) of one row of a channel filtered by its CSF: the
// weighted sum of its Gaussian terms.
void csf_row(const Plane& channel, const std::vector<WeightedKernel>& terms, int y, int x_begin, int x_end,
             PerceivedRow& row, std::vector<double>& out) {
    std::fill(out.begin() + x_begin, out.begin() + x_end, 0.0);
    row.term_row.resize(std::size_t(channel.width));
    for (const WeightedKernel& term : terms) {
        filter_separable_row(channel, term.kernel, y, x_begin, x_end, row.scratch, row.term_row.data());
        for (int x = x_begin; x < x_end; ++x) out[x] += term.weight * row.term_row[std::size_t(x)];
    }
}

void perceive_row(const Opponent& image, const Kernels& k, int y, int x_begin, int x_end, PerceivedRow& row) {
    const std::size_t width = std::size_t(image.channels[0].width);
    for (auto* v : {&row.lab[0], &row.lab[1], &row.lab[2], &row.edges, &row.points, &row.gx, &row.gy})
        v->resize(width);
    for (int c = 0; c < 3; ++c) csf_row(image.channels[c], k.csf[c], y, x_begin, x_end, row, row.lab[c]);
    for (int x = x_begin; x < x_end; ++x) {
        // The colour pipeline: back to linear RGB, clamped, then CIELAB with the Hunt adjustment.
        Vector3 v(row.lab[0][x], row.lab[1][x], row.lab[2][x]);
        Vector3 rgb = (xyz_to_rgb() * ycxcz_to_xyz(v)).cwiseMax(0.0).cwiseMin(1.0);
        Vector3 lab = linear_rgb_to_hunt_lab(rgb);
        for (int c = 0; c < 3; ++c) row.lab[c][x] = lab[c];
    }
    // The feature pipeline filters Y / Yn = (Yy + 16) / 116: every detector's
    // weights sum to 0, so filtering Yy and dividing by 116 is the same.
    auto magnitude = [&](const SeparableKernel& along_x, const SeparableKernel& along_y,
                         std::vector<double>& out) {
        filter_separable_row(image.channels[0], along_x, y, x_begin, x_end, row.scratch, row.gx.data());
        filter_separable_row(image.channels[0], along_y, y, x_begin, x_end, row.scratch, row.gy.data());
        for (int x = x_begin; x < x_end; ++x)
            out[x] = std::sqrt(row.gx[x] * row.gx[x] + row.gy[x] * row.gy[x]) / 116;
    };
    magnitude(k.edge_x, k.edge_y, row.edges);
    magnitude(k.point_x, k.point_y, row.points);
}

// The largest radius of any of FLIP's filters: a pixel's perceived values
// depend on the pixels at most this far from it, horizontally or vertically.
int reach(const Kernels& k) {
    std::size_t taps = 0;
    for (const auto& terms : k.csf)
        for (const WeightedKernel& t : terms)
            taps = std::max({taps, t.kernel.horizontal.size(), t.kernel.vertical.size()});
    for (const SeparableKernel* f : {&k.edge_x, &k.edge_y, &k.point_x, &k.point_y})
        taps = std::max({taps, f->horizontal.size(), f->vertical.size()});
    return int(taps / 2);
}

// Per row, the columns [begin, end) whose error can differ from 0: those
// within `reach` of a pixel where the images differ. Elsewhere both images'
// filters see the same pixels, so both perceive the same values bit for bit
// and the error is exactly 0 (identical parts of an LoD and its original
// are skipped, not computed).
std::vector<std::pair<int, int>> columns_to_compare(const Image8& a, const Image8& b, int reach) {
    const int width = a.width, height = a.height;
    std::vector<std::pair<int, int>> differing(std::size_t(height), {width, 0}),
        out(differing.size(), {0, 0});
    for (int y = 0; y < height; ++y) {
        auto& [begin, end] = differing[std::size_t(y)];
        for (int x = 0; x < width; ++x)
            if (!std::equal(a.at(x, y), a.at(x, y) + 3, b.at(x, y))) {
                begin = std::min(begin, x);
                end = x + 1;
            }
    }
    for (int y = 0; y < height; ++y) {
        int begin = width, end = 0;
        for (int z = std::max(0, y - reach); z <= std::min(height - 1, y + reach); ++z) {
            begin = std::min(begin, differing[std::size_t(z)].first);
            end = std::max(end, differing[std::size_t(z)].second);
        }
        if (begin < end) out[std::size_t(y)] = {std::max(0, begin - reach), std::min(width, end + reach)};
    }
    return out;
}

void check_rgb(const Image8& image) {
    if (image.channels < 3) throw std::invalid_argument("flip: RGB images expected");
}

}  // namespace

FlipReference prepare_flip_reference(const Image8& reference, double ppd, int threads) {
    check_rgb(reference);
    const Kernels kernels = flip_kernels(ppd);
    const Opponent opponent = to_ycxcz(reference, threads);
    FlipReference out;
    out.pixels_per_degree = ppd;
    out.image = reference;
    for (Plane* p : {&out.lab[0], &out.lab[1], &out.lab[2], &out.edges, &out.points})
        *p = Plane(reference.width, reference.height, 1);
    parallel_for(std::size_t(reference.height), threads, [&](std::size_t row) {
        thread_local PerceivedRow r;
        const int y = int(row);
        perceive_row(opponent, kernels, y, 0, reference.width, r);
        for (int c = 0; c < 3; ++c) std::copy(r.lab[c].begin(), r.lab[c].end(), out.lab[c].at(0, y));
        std::copy(r.edges.begin(), r.edges.end(), out.edges.at(0, y));
        std::copy(r.points.begin(), r.points.end(), out.points.at(0, y));
    });
    return out;
}

FlipResult flip(const FlipReference& reference, const Image8& test, int threads) {
    const int width = reference.edges.width, height = reference.edges.height;
    if (width != test.width || height != test.height)
        throw std::invalid_argument("flip: the images differ in size");
    check_rgb(test);
    const Kernels kernels = flip_kernels(reference.pixels_per_degree);
    const Opponent test_opponent = to_ycxcz(test, threads);

    const double cmax = max_color_distance(), pccmax = pc * cmax;
    FlipResult result;
    result.error = Plane(width, height, 1);
    std::vector<double> row_sums(std::size_t(height), 0.0);
    const std::vector<std::pair<int, int>> columns =
        columns_to_compare(reference.image, test, reach(kernels));
    parallel_for(row_sums.size(), threads, [&](std::size_t row) {
        thread_local PerceivedRow t;
        const int y = int(row);
        const auto [x_begin, x_end] = columns[row];
        if (x_begin == x_end) return;
        perceive_row(test_opponent, kernels, y, x_begin, x_end, t);
        const double* r_lab[3] = {reference.lab[0].at(0, y), reference.lab[1].at(0, y),
                                  reference.lab[2].at(0, y)};
        const double *r_edges = reference.edges.at(0, y), *r_points = reference.points.at(0, y);
        double* error_row = result.error.at(0, y);
        double sum = 0;
        for (int x = x_begin; x < x_end; ++x) {
            Vector3 p(r_lab[0][x], r_lab[1][x], r_lab[2][x]), q(t.lab[0][x], t.lab[1][x], t.lab[2][x]);
            // Colour error: HyAB^qc, [0, pc cmax) mapped linearly onto [0, pt), the rest onto [pt, 1].
            // (pow(0, y > 0) is 0 and pow(x, 1) is x: equal pixels skip both pows.)
            const double distance = hyab(p, q);
            double color = distance == 0 ? 0 : std::pow(distance, qc);
            color = color < pccmax ? pt / pccmax * color : pt + (color - pccmax) / (cmax - pccmax) * (1 - pt);
            // Feature error: the larger of the edge and point differences.
            double edge = std::abs(r_edges[x] - t.edges[x]), point = std::abs(r_points[x] - t.points[x]);
            const double largest = std::max(edge, point);
            double feature = largest == 0 ? 0 : std::pow(largest / std::numbers::sqrt2, qf);
            double error = feature == 0 ? color : std::pow(color, 1 - feature);
            error_row[x] = error;
            sum += error;
        }
        row_sums[row] = sum;
    });
    double total = std::accumulate(row_sums.begin(), row_sums.end(), 0.0);
    result.mean = result.error.empty() ? 0 : total / (double(width) * height);
    return result;
}

FlipResult flip(const Image8& reference, const Image8& test, double ppd, int threads) {
    if (reference.width != test.width || reference.height != test.height)
        throw std::invalid_argument("flip: the images differ in size");
    check_rgb(test);
    return flip(prepare_flip_reference(reference, ppd, threads), test, threads);
}

double covered_mean(const Plane& error, const Coverage& reference, const Coverage& test) {
    if (reference.width != error.width || reference.height != error.height || test.width != error.width ||
        test.height != error.height)
        throw std::invalid_argument("covered_mean: the error and the coverages differ in size");
    double sum = 0;
    std::size_t covered = 0;
    for (std::size_t i = 0; i < reference.covered.size(); ++i)
        if (reference.covered[i] || test.covered[i]) {
            sum += error.pixels[i];
            ++covered;
        }
    return covered ? sum / double(covered) : 0;
}

}  // namespace boxlod
