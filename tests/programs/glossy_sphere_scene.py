#!/usr/bin/env python3
"""The Slurm tests' scene: a glossy sphere on a ground, and 32 x 16 Radiance .hdr maps, each a sky
over a dark ground with a one-texel hot spot of the given radiance.
    glossy_sphere_scene.py FOLDER NAME=SUN [NAME=SUN...]
writes FOLDER/scene.json (its environment: the first map) and FOLDER/NAME.hdr for each."""
import json
import math
import os
import sys


def rgbe(r, g, b):
    m = max(r, g, b)
    mant, e = math.frexp(m)
    s = mant * 256.0 / m
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])


def main(folder, maps):
    os.makedirs(folder, exist_ok=True)
    w, h = 32, 16
    names = []
    for entry in maps:
        name, sun = entry.split("=")
        sun = float(sun)
        pixels = b"".join(rgbe(sun, 0.95 * sun, 0.75 * sun) if (x, y) == (8, 3) else
                          rgbe(0.6, 0.8, 1.0) if y < h // 2 else rgbe(0.2, 0.2, 0.25)
                          for y in range(h) for x in range(w))
        with open(os.path.join(folder, name + ".hdr"), "wb") as f:
            f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w) + pixels)
        names.append(name)
    scene = {"models": [{"shape": "sphere", "material": {"baseColor": [0.8, 0.5, 0.3], "metallic": 0.0, "roughness": 0.4}}],
             "ground": {}, "environment": {"file": names[0] + ".hdr"},
             "camera": {"position": [0, 0.6, 3.2], "target": [0, 0, 0], "yfov": 45}}
    with open(os.path.join(folder, "scene.json"), "w") as f:
        json.dump(scene, f)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
