#!/usr/bin/env python3
"""SSIM of two 8-bit sRGB images by scikit-image, as `boxlod compare` defines it.

Usage: ssim_reference.py A.png B.png  -> prints the mean SSIM with 17 digits.
Luma is ITU-R BT.601 (0.299 R + 0.587 G + 0.114 B) of the sRGB-encoded values
in [0, 1]; structural_similarity runs with gaussian_weights=True, sigma=1.5,
use_sample_covariance=False, data_range=1 (Wang et al. 2004).
"""
import sys

import numpy as np
from skimage.io import imread
from skimage.metrics import structural_similarity


def luma(path):
    image = imread(path)
    if image.ndim != 3 or image.shape[2] < 3 or image.dtype != np.uint8:
        sys.exit(f"{path}: expected an 8-bit RGB image, got shape {image.shape} {image.dtype}")
    rgb = image[..., :3].astype(np.float64) / 255.0
    return 0.299 * rgb[..., 0] + 0.587 * rgb[..., 1] + 0.114 * rgb[..., 2]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = luma(sys.argv[1]), luma(sys.argv[2])
    value = structural_similarity(a, b, gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
                                  data_range=1.0)
    print(f"{value:.17g}")


if __name__ == "__main__":
    main()
