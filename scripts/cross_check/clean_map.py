"""blender -b --python clean_map.py -- IN.exr OUT.exr

The map with its negative texels (DWAB ringing) set to 0, uncompressed, so that both tracers read
the same non-negative radiance: iblkit repairs negative texels by moving energy
(docs/robustness.md) and Cycles keeps them, and that difference is not what the cross-check tests.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_io import arguments, load_rgb  # noqa: E402
from exr_write import write_exr  # noqa: E402

source, target = arguments()[:2]
rgb = load_rgb(source)
negative = rgb < 0
print("clean_map: %s: %d negative values, %.3g%% of the absolute energy"
      % (os.path.basename(source), int(negative.sum()), 100 * float(-rgb[negative].sum() / np.abs(rgb).sum())))
write_exr(target, np.maximum(rgb, 0))
