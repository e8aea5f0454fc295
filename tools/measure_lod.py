#!/usr/bin/env python3
"""Compares each view drawn with automatic levels of detail against the same view with every plant
as mesh 1 (what a player compares the far levels with).

    tools/measure_lod.py DIR VIEW...

For each VIEW it reads DIR/VIEW.auto.png, DIR/VIEW.mesh1.png and DIR/VIEW.mask.png (the impostors
alone on black) and prints: the structural similarity (SSIM, luminance, 7 × 7 windows, the usual
constants K1 = 0.01, K2 = 0.03), the mean absolute difference, the impostor region's share of the
picture and its mean brightness in the automatic picture relative to the full-mesh one.
"""
import sys

import numpy as np
from PIL import Image


def luminance(path):
    rgb = np.asarray(Image.open(path).convert("RGB"), dtype=np.float64) / 255.0
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def box_mean(values, size=7):
    """Mean over size × size windows (valid positions only), with an integral image."""
    integral = np.pad(values, ((1, 0), (1, 0))).cumsum(0).cumsum(1)
    total = integral[size:, size:] - integral[:-size, size:] - integral[size:, :-size] + integral[:-size, :-size]
    return total / (size * size)


def ssim(a, b):
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    mean_a, mean_b = box_mean(a), box_mean(b)
    var_a = box_mean(a * a) - mean_a ** 2
    var_b = box_mean(b * b) - mean_b ** 2
    covariance = box_mean(a * b) - mean_a * mean_b
    index = ((2 * mean_a * mean_b + c1) * (2 * covariance + c2)) / ((mean_a ** 2 + mean_b ** 2 + c1) * (var_a + var_b + c2))
    return float(index.mean())


def main(folder, views):
    print("| view | SSIM to mesh 1 | mean abs. difference | impostor region | its brightness vs mesh 1 |")
    print("|---|---|---|---|---|")
    for view in views:
        auto = luminance(f"{folder}/{view}.auto.png")
        full = luminance(f"{folder}/{view}.mesh1.png")
        mask = luminance(f"{folder}/{view}.mask.png") > 0.02
        share = float(mask.mean())
        ratio = float(auto[mask].mean() / max(full[mask].mean(), 1e-6)) if mask.any() else float("nan")
        print(f"| {view} | {ssim(auto, full):.3f} | {float(np.abs(auto - full).mean()):.4f} | {100 * share:.1f} % | "
              + (f"{ratio:.3f} |" if mask.any() else "— |"))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
