"""blender -b --python compare.py -- CASE IBLKIT_A IBLKIT_B CYCLES_A CYCLES_B MASK DEPTH MAP [IBLKIT_NORMAL CYCLES_NORMAL]

One case of the cross-check: the mean radiance of each region (the objects, the ground, the
sky; pixels next to another region left out, where the two tracers' edges differ by their pixel
sampling) in iblkit's and Cycles' images, each the mean of two renders with different seeds.
The standard error of a region's mean comes from the two renders' pixel differences:
var(pixel of the mean) ~ (a - b)^2 / 4, summed over the region's n pixels and divided by n^2.
Prints one JSON line: per region, the two means (luminance), Cycles / iblkit and z =
(Cycles - iblkit) / the difference's standard error. With the normal passes, the objects are
also compared where the two shading normals agree within 1 degree.

A third opinion needs no tracer: the far ground (more than 9.5 m from the camera, beyond the
sphere's shadow) is a Lambert plane of albedo 0.8 under the map, whose radiance is 0.8 / pi
times the map's upward irradiance E_up = sum of L cos(theta) Omega over its texels (MAP, read
here). The sphere hides a little of the sky there and reflects a little onto it: a few tenths of
a percent. Each tracer's far ground over that value is printed as "far ground / analytic".
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_io import arguments, load_rgb  # noqa: E402
from environment import LUMINANCE as luminance, upward_irradiance  # noqa: E402

args = arguments()
name = args[0]
ib_a, ib_b, cy_a, cy_b, mask, depth, environment = (load_rgb(p) for p in args[1:8])
objects = mask[..., 0] > 0.999
sky = ~np.isfinite(depth[..., 0]) | (depth[..., 0] <= 0) | (depth[..., 0] > 1e20)
ground = ~objects & ~sky
label = objects * 1 + ground * 2
padded = np.pad(label, 1, mode="edge")
inner = np.ones_like(objects)
for dy in (-1, 0, 1):
    for dx in (-1, 0, 1):
        inner &= padded[1 + dy:1 + dy + label.shape[0], 1 + dx:1 + dx + label.shape[1]] == label
regions = {"objects": objects & inner, "ground": ground & inner, "sky": sky & inner}
if len(args) > 9:
    n_ib, n_cy = load_rgb(args[8]), load_rgb(args[9])
    n_cy = np.stack([n_cy[..., 0], n_cy[..., 2], -n_cy[..., 1]], -1)  # Blender +Z up to glTF +Y up
    cosine = (n_ib * n_cy).sum(-1) / np.maximum(np.linalg.norm(n_ib, axis=-1) * np.linalg.norm(n_cy, axis=-1), 1e-12)
    regions["objects, normals within 1 degree"] = regions["objects"] & (cosine > np.cos(np.radians(1.0)))
result = {"case": name}
for region, where in regions.items():
    n = int(where.sum())
    if n == 0:
        continue
    stats = {}
    for who, (a, b) in (("iblkit", (ib_a, ib_b)), ("cycles", (cy_a, cy_b))):
        la, lb = a[where] @ luminance, b[where] @ luminance
        stats[who] = (float((la + lb).mean() / 2), float(((la - lb) ** 2 / 4).sum() / n ** 2))
    (mi, vi), (mc, vc) = stats["iblkit"], stats["cycles"]
    error = np.sqrt(vi + vc)
    result[region] = {"pixels": n, "iblkit": mi, "cycles": mc, "ratio": mc / mi,
                      "z": float((mc - mi) / error) if error > 0 else 0.0}
analytic = 0.8 / np.pi * upward_irradiance(environment)
far = ground & inner & (depth[..., 0] > 9.5)
if far.any():
    result["far ground / analytic"] = {
        "pixels": int(far.sum()), "analytic": analytic,
        "iblkit": float(((ib_a[far] + ib_b[far]) @ luminance).mean() / 2 / analytic),
        "cycles": float(((cy_a[far] + cy_b[far]) @ luminance).mean() / 2 / analytic)}
print("CROSS_CHECK " + json.dumps(result))
