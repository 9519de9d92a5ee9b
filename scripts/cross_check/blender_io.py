"""Reading EXR files inside Blender (bpy loads them as linear floats, row 0 at the bottom)."""
import bpy
import numpy as np


def load_rgb(path):
    """The file's RGB as an H x W x 3 float64 array, row 0 at the top."""
    image = bpy.data.images.load(path)
    width, height = image.size
    pixels = np.empty(width * height * 4, np.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(height, width, 4)[::-1, :, :3].astype(np.float64)


def arguments():
    import sys
    return sys.argv[sys.argv.index("--") + 1:]
