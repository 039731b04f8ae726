// Full-reference image metrics on 8-bit sRGB images (any channel count >= 3;
// alpha and further channels are ignored): RMSE, PSNR and SSIM.
// Both images must have the same size (std::invalid_argument otherwise).
#pragma once
#include "renderer/image.h"
#include "toolkit/metrics/separable_filter.h"

namespace boxlod {

// Root mean squared error of the sRGB-encoded values scaled to [0, 1], over
// the R, G and B values of every pixel. 0 for identical images.
double rmse(const Image8& a, const Image8& b);

// Peak signal-to-noise ratio in dB for peak 1: 20 log10(1 / rmse). +infinity
// for identical images (printed as `inf` by the CLI).
double psnr_from_rmse(double rmse);
double psnr(const Image8& a, const Image8& b);

// Per pixel: the root mean square over R, G, B of the difference in [0, 1]
// (the heat map's `rmse` error; its mean square over the image is rmse^2).
Plane rgb_error_map(const Image8& a, const Image8& b);

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality assessment:
// from error visibility to structural similarity", eq. 13 with the Gaussian
// window of section III-C) computed as scikit-image's structural_similarity
// with gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
// data_range=1: the window is a Gaussian of sigma 1.5 truncated at 3.5 sigma
// (radius int(3.5 * 1.5 + 0.5) = 5, 11x11 taps), K1 = 0.01, K2 = 0.03, and
// the mean leaves out the 5-pixel border the window cannot fully cover.
// SSIM is taken on luma: ITU-R BT.601 weights 0.299 R + 0.587 G + 0.114 B
// applied to the sRGB-encoded values in [0, 1] (not to linear light).
// Images smaller than 11x11 throw std::invalid_argument.
double ssim(const Image8& a, const Image8& b, int threads = 0);

// The BT.601 luma plane used by ssim, values in [0, 1].
Plane luma_plane(const Image8& image);

}  // namespace boxlod
