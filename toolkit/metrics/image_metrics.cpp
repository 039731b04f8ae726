#include "toolkit/metrics/image_metrics.h"

#include "base/parallel.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace boxlod {

namespace {

void require_comparable(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("image metrics: the images differ in size");
    if (a.channels < 3 || b.channels < 3) throw std::invalid_argument("image metrics: RGB images expected");
}

// SSIM constants (Wang et al. 2004, section III-B and III-C; scikit-image defaults).
constexpr double ssim_sigma = 1.5;
constexpr double ssim_truncate = 3.5;  // scipy.ndimage.gaussian_filter's cut-off, in sigmas
constexpr double ssim_k1 = 0.01, ssim_k2 = 0.03, ssim_data_range = 1.0;

Plane product(const Plane& a, const Plane& b) {
    Plane out(a.width, a.height, 1);
    for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = a.pixels[i] * b.pixels[i];
    return out;
}

}  // namespace

double rmse(const Image8& a, const Image8& b) {
    require_comparable(a, b);
    // Integer sum of squared 8-bit differences: exact, so the result is too.
    std::uint64_t sum = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                int d = int(a.at(x, y)[c]) - int(b.at(x, y)[c]);
                sum += std::uint64_t(d * d);
            }
    std::uint64_t count = std::uint64_t(a.width) * a.height * 3;
    if (count == 0) return 0;
    return std::sqrt(double(sum) / double(count)) / 255.0;
}

double psnr_from_rmse(double rmse) {
    if (rmse == 0) return std::numeric_limits<double>::infinity();
    return -20.0 * std::log10(rmse);
}

double psnr(const Image8& a, const Image8& b) { return psnr_from_rmse(rmse(a, b)); }

Plane rgb_error_map(const Image8& a, const Image8& b) {
    require_comparable(a, b);
    Plane out(a.width, a.height, 1);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int sum = 0;
            for (int c = 0; c < 3; ++c) {
                int d = int(a.at(x, y)[c]) - int(b.at(x, y)[c]);
                sum += d * d;
            }
            *out.at(x, y) = std::sqrt(sum / 3.0) / 255.0;
        }
    return out;
}

Plane luma_plane(const Image8& image) {
    Plane out(image.width, image.height, 1);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            // ITU-R BT.601 luma weights on the encoded values.
            *out.at(x, y) = 0.299 * (p[0] / 255.0) + 0.587 * (p[1] / 255.0) + 0.114 * (p[2] / 255.0);
        }
    return out;
}

double ssim(const Image8& a, const Image8& b, int threads) {
    require_comparable(a, b);
    const int radius = int(ssim_truncate * ssim_sigma + 0.5);
    const int window = 2 * radius + 1;
    if (a.width < window || a.height < window)
        throw std::invalid_argument("ssim: images must be at least " + std::to_string(window) + "x" +
                                    std::to_string(window) + " pixels");
    std::vector<double> gaussian = sampled_gaussian(ssim_sigma, radius);
    const SeparableKernel kernel{gaussian, gaussian};
    const Plane x = luma_plane(a), y = luma_plane(b);
    const Plane xx = product(x, x), yy = product(y, y), xy = product(x, y);

    const double c1 = (ssim_k1 * ssim_data_range) * (ssim_k1 * ssim_data_range);
    const double c2 = (ssim_k2 * ssim_data_range) * (ssim_k2 * ssim_data_range);
    // The mean skips the border where the window would leave the image, as
    // scikit-image's crop(S, pad); there the border rule does not matter.
    const int x0 = radius, x1 = a.width - radius, y0 = radius, y1 = a.height - radius;
    std::vector<double> row_sums(std::size_t(y1 - y0), 0.0);
    parallel_for(row_sums.size(), threads, [&](std::size_t row) {
        const int r = y0 + int(row);
        // Local means, second moments and covariance (Wang et al. 2004, eq. 14-16), one row at a time.
        std::vector<double> scratch, mx(a.width), my(a.width), mxx(a.width), myy(a.width), mxy(a.width);
        filter_separable_row(x, kernel, r, scratch, mx.data());
        filter_separable_row(y, kernel, r, scratch, my.data());
        filter_separable_row(xx, kernel, r, scratch, mxx.data());
        filter_separable_row(yy, kernel, r, scratch, myy.data());
        filter_separable_row(xy, kernel, r, scratch, mxy.data());
        double sum = 0;
        for (int i = x0; i < x1; ++i) {
            double ux = mx[i], uy = my[i];
            double vx = mxx[i] - ux * ux, vy = myy[i] - uy * uy, vxy = mxy[i] - ux * uy;
            // Wang et al. 2004, eq. 13.
            sum += ((2 * ux * uy + c1) * (2 * vxy + c2)) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
        }
        row_sums[row] = sum;
    });
    double total = std::accumulate(row_sums.begin(), row_sums.end(), 0.0);
    return total / (double(x1 - x0) * double(y1 - y0));
}

}  // namespace boxlod
