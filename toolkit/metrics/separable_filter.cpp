#include "toolkit/metrics/separable_filter.h"

#include "base/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace boxlod {

namespace {

int radius_of(const std::vector<double>& taps) {
    if (taps.size() % 2 != 1)
        throw std::invalid_argument("filter_separable: kernels need an odd number of taps");
    return int(taps.size() / 2);
}

// out[x] = sum over t of w[t] * rows[t][x], summed from 0 in the order of t:
// the filters' whole inner loop. Each block of columns keeps its sums in
// registers across the taps (one load per tap instead of a load and a store
// of the sums), and every output gets the same multiplies and adds in the
// same order whatever the block or vector width: the AVX2 clone (chosen at
// run time where the CPU has it) gives the same bits as the default one.
__attribute__((target_clones("avx2", "default"))) void weighted_sum(double* __restrict out,
                                                                    const double* const* rows,
                                                                    const double* w, int taps, int n) {
    // Four vectors of four sums (GCC's vector extension: AVX2 registers in
    // that clone, pairs of SSE2 registers in the default one).
    using Vector4 = double __attribute__((vector_size(32)));
    int x = 0;
    for (; x + 16 <= n; x += 16) {
        Vector4 s0 = {}, s1 = {}, s2 = {}, s3 = {};
        for (int t = 0; t < taps; ++t) {
            const double* row = rows[t] + x;
            const Vector4 weight = {w[t], w[t], w[t], w[t]};
            Vector4 r0, r1, r2, r3;
            std::memcpy(&r0, row, sizeof r0), std::memcpy(&r1, row + 4, sizeof r1);
            std::memcpy(&r2, row + 8, sizeof r2), std::memcpy(&r3, row + 12, sizeof r3);
            s0 += weight * r0;
            s1 += weight * r1;
            s2 += weight * r2;
            s3 += weight * r3;
        }
        std::memcpy(out + x, &s0, sizeof s0), std::memcpy(out + x + 4, &s1, sizeof s1);
        std::memcpy(out + x + 8, &s2, sizeof s2), std::memcpy(out + x + 12, &s3, sizeof s3);
    }
    for (; x < n; ++x) {
        double sum = 0;
        for (int t = 0; t < taps; ++t) sum += w[t] * rows[t][x];
        out[x] = sum;
    }
}

}  // namespace

void filter_separable_row(const Plane& in, const SeparableKernel& kernel, int y, std::vector<double>& scratch,
                          double* out) {
    filter_separable_row(in, kernel, y, 0, in.width, scratch, out);
}

void filter_separable_row(const Plane& in, const SeparableKernel& kernel, int y, int x_begin, int x_end,
                          std::vector<double>& scratch, double* out) {
    const int rh = radius_of(kernel.horizontal), rv = radius_of(kernel.vertical);
    const int width = in.width, height = in.height;
    if (x_begin < 0 || x_end > width || x_begin >= x_end) return;
    // The vertical pass into one row of the columns the outputs reach
    // (consecutive rows reuse the same source rows from cache), with the
    // columns past the image's edges replicated, then the horizontal pass
    // over that row: neither inner loop clamps and both vectorize.
    thread_local std::vector<const double*> rows;
    rows.resize(std::max(kernel.vertical.size(), kernel.horizontal.size()));
    const int first = x_begin - rh, last = x_end + rh;  // the columns reached, [first, last)
    const int inside_first = std::max(first, 0), inside_last = std::min(last, width);
    scratch.resize(std::size_t(last - first));
    auto column = [&](int c) -> double& { return scratch[std::size_t(c - first)]; };
    for (std::size_t t = 0; t < kernel.vertical.size(); ++t)
        rows[t] = in.at(inside_first, std::clamp(y + int(t) - rv, 0, height - 1));
    weighted_sum(&column(inside_first), rows.data(), kernel.vertical.data(), int(kernel.vertical.size()),
                 inside_last - inside_first);
    for (int c = first; c < inside_first; ++c) column(c) = column(0);
    for (int c = inside_last; c < last; ++c) column(c) = column(width - 1);
    for (std::size_t t = 0; t < kernel.horizontal.size(); ++t) rows[t] = scratch.data() + t;
    weighted_sum(out + x_begin, rows.data(), kernel.horizontal.data(), int(kernel.horizontal.size()),
                 x_end - x_begin);
}

Plane filter_separable(const Plane& in, const SeparableKernel& kernel, int threads) {
    radius_of(kernel.horizontal);  // both kernels are checked even for an empty image
    radius_of(kernel.vertical);
    Plane out(in.width, in.height, 1);
    if (in.empty()) return out;
    parallel_for(std::size_t(in.height), threads, [&](std::size_t y) {
        std::vector<double> scratch;
        filter_separable_row(in, kernel, int(y), scratch, out.at(0, int(y)));
    });
    return out;
}

std::vector<double> sampled_gaussian(double sigma, int radius) {
    std::vector<double> taps(std::size_t(2 * radius + 1));
    double sum = 0;
    for (int i = -radius; i <= radius; ++i)
        sum += taps[i + radius] = std::exp(-0.5 * double(i) * i / (sigma * sigma));
    for (double& t : taps) t /= sum;
    return taps;
}

}  // namespace boxlod
