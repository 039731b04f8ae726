#include "experiments/separable_filter.h"

#include "base/parallel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boxlod {

namespace {

int radius_of(const std::vector<double>& taps) {
    if (taps.size() % 2 != 1) throw std::invalid_argument("filter_separable: kernels need an odd number of taps");
    return int(taps.size() / 2);
}

// out[x] += w * in[x]: the filters' whole inner loop. Elementwise, so every
// output gets the same multiply and add in the same order whatever the vector
// width: the AVX2 clone (chosen at run time where the CPU has it; 4 doubles a
// step instead of SSE2's 2) gives the same bits as the default one.
__attribute__((target_clones("avx2", "default"))) void add_scaled(double* __restrict out, const double* __restrict in, double w, int n) {
    for (int x = 0; x < n; ++x) out[x] += w * in[x];
}

}  // namespace

void filter_separable_row(const Plane& in, const SeparableKernel& kernel, int y, std::vector<double>& scratch,
                          double* out) {
    const int rh = radius_of(kernel.horizontal), rv = radius_of(kernel.vertical);
    const int width = in.width, height = in.height;
    // The vertical pass into one row (consecutive rows reuse the same source
    // rows from cache), then the horizontal pass over that row copied with
    // replicated borders, so neither inner loop clamps and both vectorize.
    scratch.assign(std::size_t(width) + 2 * rh, 0.0);
    double* column = scratch.data() + rh;
    for (std::size_t t = 0; t < kernel.vertical.size(); ++t) {
        const double w = kernel.vertical[t];
        add_scaled(column, in.at(0, std::clamp(y + int(t) - rv, 0, height - 1)), w, width);
    }
    for (int i = 0; i < rh; ++i) scratch[std::size_t(i)] = column[0], scratch[std::size_t(rh + width + i)] = column[width - 1];
    std::fill(out, out + width, 0.0);
    for (std::size_t t = 0; t < kernel.horizontal.size(); ++t) {
        add_scaled(out, scratch.data() + t, kernel.horizontal[t], width);
    }
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
    for (int i = -radius; i <= radius; ++i) sum += taps[i + radius] = std::exp(-0.5 * double(i) * i / (sigma * sigma));
    for (double& t : taps) t /= sum;
    return taps;
}

}  // namespace boxlod
