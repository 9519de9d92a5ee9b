"""blender -b --python make_sun_map.py -- OUT.exr [WIDTH]

A large synthetic map with a real-sized sun, as users' HDR photographs have: WIDTH x WIDTH/2
(default 4096), a sky brighter towards the zenith over a dim ground, and a sun disk of 0.265
degrees radius (about 30 texels at 4096) 35 degrees up, whose irradiance on a plane facing it is
about 20 times the sky's. It tests the environment sampler at the size where float CDFs and
guide tables lose precision, against Cycles'.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_io import arguments  # noqa: E402
from exr_write import write_exr  # noqa: E402

args = arguments()
width = int(args[1]) if len(args) > 1 else 4096
height = width // 2
u = (np.arange(width) + 0.5) / width
v = (np.arange(height) + 0.5) / height
lon = 2 * math.pi * (0.5 - u)[None, :]
lat = math.pi * (0.5 - v)[:, None]
d = np.stack(np.broadcast_arrays(np.cos(lat) * np.sin(lon), np.sin(lat) + 0 * lon, np.cos(lat) * np.cos(lon)), -1)
up = np.clip(d[..., 1], 0, 1)
sky = np.where(d[..., 1:2] > 0, np.array([0.35, 0.5, 0.9]) * (0.3 + 0.7 * up[..., None]), np.array([0.12, 0.1, 0.08]))
elevation, azimuth, radius = math.radians(35), math.radians(-40), math.radians(0.265)
sun = np.array([math.cos(elevation) * math.sin(azimuth), math.sin(elevation), math.cos(elevation) * math.cos(azimuth)])
in_sun = (d @ sun) >= math.cos(radius)
solid_angle = 2 * math.pi * (1 - math.cos(radius))
radiance = 20 * math.pi * 0.6 / solid_angle  # irradiance about 20 x a sky of radiance about 0.6
rgb = sky.copy()
rgb[in_sun] = radiance * np.array([1.0, 0.95, 0.85])
print("make_sun_map: %d x %d, sun %d texels of radiance %.3g" % (width, height, int(in_sun.sum()), radiance))
write_exr(args[0], rgb)
