"""blender -b --python expected_differences.py -- [SKY.exr]

The differences between Cycles 3.4 and iblkit that follow from their definitions, computed
without either tracer (docs/reference-tracer.md, "Against another path tracer"):

1. GGX masking: Cycles' separable Smith G1(i) G1(o) over iblkit's height-correlated
   1 / (1 + Lambda(i) + Lambda(o)), as the directional albedo of a white metal (F = 1) averaged
   over a sphere's pixels (view cosine mu from MU_MIN, weight 2 mu) under a uniform light.
2. 8-bit sRGB textures: Cycles filters the bytes, then decodes; iblkit (and GL) decode, then filter.
   The mean over bilinear lookups of make_sphere_glb.py's base colour texture.
3. Negative texels: a map's upward irradiance (sum of L cos Omega) clamped over as it is.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_io import arguments, load_rgb  # noqa: E402
from environment import LUMINANCE, upward_irradiance  # noqa: E402
from make_sphere_glb import base_colour_bytes  # noqa: E402

rng = np.random.default_rng(1)


def ggx_albedos(alpha, mu, n=200000):
    """(height-correlated, separable) directional albedo of GGX with F = 1, by sampling D cos(m)."""
    wo = np.array([math.sqrt(1 - mu * mu), 0.0, mu])
    u1, u2 = rng.random(n), rng.random(n)
    cos_m = 1 / np.sqrt(1 + alpha * alpha * u1 / (1 - u1))
    sin_m = np.sqrt(1 - cos_m ** 2)
    m = np.stack([sin_m * np.cos(2 * math.pi * u2), sin_m * np.sin(2 * math.pi * u2), cos_m], -1)
    o_m = m @ wo
    wi = 2 * o_m[:, None] * m - wo
    valid = (wi[:, 2] > 0) & (o_m > 0)
    lam = lambda c: (-1 + np.sqrt(1 + alpha * alpha * (1 - c * c) / (c * c))) / 2  # noqa: E731
    li = np.where(valid, lam(np.clip(wi[:, 2], 1e-9, 1)), 0)
    lo = lam(mu)
    weight = np.where(valid, o_m / (mu * cos_m), 0)  # f cos / pdf without G, pdf = D cos_m / (4 o.m)
    return float((weight / (1 + li + lo)).mean()), float((weight / ((1 + li) * (1 + lo))).mean())


def srgb_decode(c):
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def bilinear_means(texels, n=2000000):
    size = texels.shape[0]
    x, y = rng.random(n) * size - 0.5, rng.random(n) * size - 0.5
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    fx, fy = (x - x0)[:, None], (y - y0)[:, None]
    at = lambda img, yy, xx: img[np.mod(yy, size), np.mod(xx, size)]  # noqa: E731

    def lookup(img):
        return ((1 - fx) * (1 - fy) * at(img, y0, x0) + fx * (1 - fy) * at(img, y0, x0 + 1)
                + (1 - fx) * fy * at(img, y0 + 1, x0) + fx * fy * at(img, y0 + 1, x0 + 1))
    return lookup(srgb_decode(texels)).mean(0) @ LUMINANCE, srgb_decode(lookup(texels)).mean(0) @ LUMINANCE


args = arguments()
for roughness in (0.3, 0.7):
    mus = (np.arange(40) + 0.5) / 40
    mus = mus[mus >= 0.33]
    pairs = np.array([ggx_albedos(roughness ** 2, mu) for mu in mus])
    ratio = (pairs[:, 1] * 2 * mus).sum() / (pairs[:, 0] * 2 * mus).sum()
    print("expected: GGX roughness %.1f, separable / height-correlated masking over the sphere: %.4f" % (roughness, ratio))
ours, cycles = bilinear_means(base_colour_bytes().astype(np.float64) / 255)
print("expected: base colour texture, filter-then-decode / decode-then-filter: %.4f" % (cycles / ours))
if args:
    raw = load_rgb(args[0])
    print("expected: %s, upward irradiance clamped / as it is: %.4f"
          % (os.path.basename(args[0]), upward_irradiance(np.maximum(raw, 0)) / upward_irradiance(raw)))
