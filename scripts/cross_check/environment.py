"""Sums over a lat-long map (docs/conventions.md): luminance and the upward irradiance."""
import math

import numpy as np

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # Rec. 709


def upward_irradiance(rgb):
    """E_up, the luminance of the sum of L cos(theta) Omega over the texels of an H x W x 3 map
    (theta from +Y; Omega a texel's exact solid angle, the area between its row's latitudes)."""
    height, width, _ = rgb.shape
    rows = np.arange(height)
    omega = (2 * math.pi / width) * (np.sin(math.pi * (0.5 - rows / height)) - np.sin(math.pi * (0.5 - (rows + 1) / height)))
    cosine = np.maximum(np.sin(math.pi * (0.5 - (rows + 0.5) / height)), 0)
    return float(((rgb @ LUMINANCE) * (omega * cosine)[:, None]).sum())
