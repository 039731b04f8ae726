// Separable convolution of single-channel double images, the workhorse of the
// image metrics (SSIM's Gaussian window, FLIP's contrast-sensitivity and
// feature filters). Parallel over rows and deterministic: every output row is
// written by one task and every output value sums its taps in a fixed order,
// so the result is the same for any thread count.
#pragma once
#include "renderer/image.h"

#include <vector>

namespace boxlod {

using Plane = Image<double>;  // one channel

// The 2D kernel horizontal(i) * vertical(j); both of odd length, centred.
struct SeparableKernel {
    std::vector<double> horizontal, vertical;
};

// out(x, y) = sum_i horizontal[i] * sum_j vertical[j] * in(x + i - rh, y + j - rv),
// with rh, rv the kernels' radii and coordinates outside the image clamped to
// the nearest edge pixel ("replicate" borders, as the FLIP paper's code).
Plane filter_separable(const Plane& in, const SeparableKernel& kernel, int threads);

// Row y of filter_separable(in, kernel) into out[0, width), the same bits;
// for metrics that combine several filtered planes row by row without
// keeping them (large fresh planes cost more in page faults than filtering).
// `scratch` is any vector, reused between calls.
void filter_separable_row(const Plane& in, const SeparableKernel& kernel, int y, std::vector<double>& scratch,
                          double* out);
// Only out[x_begin, x_end) of that row, the same bits as the whole row's.
void filter_separable_row(const Plane& in, const SeparableKernel& kernel, int y, int x_begin, int x_end,
                          std::vector<double>& scratch, double* out);

// exp(-x^2 / (2 sigma^2)) at x = -radius..radius, scaled to sum 1.
std::vector<double> sampled_gaussian(double sigma, int radius);

}  // namespace boxlod
