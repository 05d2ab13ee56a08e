#!/usr/bin/python3
"""scikit-image's SSIM of two 8-bit RGBA PNGs' luma, as renderer/metrics/ssim.h defines it: the
reference test_ssim.cpp compares depthscope's SSIM against (Debian's python3-skimage 0.19).

  ssim_reference.py A.png B.png MAP.f64

Prints the mean SSIM (repr, every digit) and writes the full SSIM map, row by row, as
little-endian float64.
"""
import sys

import numpy as np
from PIL import Image
from skimage.metrics import structural_similarity


def luma(path):
    rgba = np.asarray(Image.open(path).convert("RGBA")).astype(np.float64)
    # Same weights and order of operations as metrics::luma, no linearisation.
    return 0.2126 * rgba[..., 0] + 0.7152 * rgba[..., 1] + 0.0722 * rgba[..., 2]


a, b = luma(sys.argv[1]), luma(sys.argv[2])
mean, full = structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
                                   use_sample_covariance=False, data_range=255, full=True)
full.astype("<f8").tofile(sys.argv[3])
print(repr(float(mean)))
