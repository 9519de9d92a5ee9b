"""An uncompressed scanline OpenEXR writer (RGB, 32-bit float), enough for the cross-check's inputs.

Blender 3.4's own image saving applies a colour transform to generated float images, so the
cleaned maps are written here, byte by byte, after the OpenEXR file layout (openexr.com,
"OpenEXR File Layout"): magic and version, the header's attributes, the line offset table, then
each scanline's channels in alphabetical order (B, G, R).
"""
import os
import struct

import numpy as np


def _attribute(name, kind, data):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data


def write_exr(path, rgb):
    """Writes an H x W x 3 array of linear floats to path (through a temporary name)."""
    rgb = np.asarray(rgb, np.float32)
    height, width, _ = rgb.shape
    channels = b"".join(c.encode() + b"\0" + struct.pack("<i", 2) + b"\0\0\0\0" + struct.pack("<ii", 1, 1)
                        for c in "BGR") + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2)
              + _attribute("channels", "chlist", channels)
              + _attribute("compression", "compression", b"\0")
              + _attribute("dataWindow", "box2i", box)
              + _attribute("displayWindow", "box2i", box)
              + _attribute("lineOrder", "lineOrder", b"\0")
              + _attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + _attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
              + _attribute("screenWindowWidth", "float", struct.pack("<f", 1.0))
              + b"\0")
    line_bytes = 8 + width * 4 * 3
    first = len(header) + 8 * height
    out = bytearray(header)
    out += b"".join(struct.pack("<Q", first + y * line_bytes) for y in range(height))
    for y in range(height):
        out += struct.pack("<ii", y, width * 12)
        out += rgb[y, :, 2].tobytes() + rgb[y, :, 1].tobytes() + rgb[y, :, 0].tobytes()
    with open(path + ".tmp", "wb") as f:
        f.write(out)
    os.replace(path + ".tmp", path)
