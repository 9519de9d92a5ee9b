"""blender -b --python make_sphere_glb.py -- OUT.glb base|normal|color

A unit UV sphere (96 x 48 segments, exact normals, no tangents: readers derive MikkTSpace ones)
with one texture: `base`, an sRGB base colour of stripes and checks that differ along u and v
(a flipped or swapped uv shows); `normal`, a tangent-space normal map of bumps tilted up to 31
degrees (factor 0.8 grey); `color`, no texture but vertex colours (COLOR_0, VEC4 float, alpha 1)
that vary smoothly with the position, multiplying a base colour factor of 0.9. Written with
Python's zlib as PNG inside a glb.
"""
import json
import math
import os
import struct
import sys
import zlib

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_io import arguments  # noqa: E402


def png(rgb8):
    height, width, _ = rgb8.shape
    raw = b"".join(b"\0" + rgb8[y].tobytes() for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def sphere(segments=96, rings=48):
    positions, uvs, indices = [], [], []
    for j in range(rings + 1):
        theta = math.pi * j / rings
        for i in range(segments + 1):
            phi = 2 * math.pi * i / segments
            positions.append((math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi)))
            uvs.append((i / segments, j / rings))
    for j in range(rings):
        for i in range(segments):
            a = j * (segments + 1) + i
            b = a + segments + 1
            if j > 0:
                indices += [a, b, a + 1]
            if j < rings - 1:
                indices += [a + 1, b, b + 1]
    return np.array(positions, np.float32), np.array(uvs, np.float32), np.array(indices, np.uint32)


def to_bytes(x):
    return (np.clip(x, 0, 1) * 255 + 0.5).astype(np.uint8)


def base_colour_bytes(size=256):
    """The base colour texture's sRGB bytes, H x W x 3."""
    u = (np.arange(size) + 0.5) / size
    U, V = np.meshgrid(u, u)
    check = (np.floor(U * 8) + np.floor(V * 4)) % 2
    return to_bytes(np.stack([0.15 + 0.8 * U, 0.15 + 0.7 * (1 - V) * check + 0.1, 0.9 - 0.7 * U * (1 - check)], -1))


def textures(size=256):
    u = (np.arange(size) + 0.5) / size
    U, V = np.meshgrid(u, u)
    tilt, periods = 0.6, 6
    normal = np.stack([-tilt * np.cos(2 * math.pi * periods * U), -0.7 * tilt * np.sin(2 * math.pi * periods * V),
                       np.ones_like(U)], -1)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    return png(base_colour_bytes(size)), png(to_bytes(normal * 0.5 + 0.5))


def vertex_colours(positions):
    """COLOR_0 of the unit sphere's vertices: each channel a smooth function of the position, in [0.1, 0.95]."""
    x, y, z = positions[:, 0], positions[:, 1], positions[:, 2]
    rgb = np.stack([0.1 + 0.85 * (x + 1) / 2, 0.1 + 0.85 * (y + 1) / 2,
                    0.525 + 0.425 * np.sin(3 * np.arctan2(z, x))], -1)
    return np.concatenate([rgb, np.ones((len(positions), 1))], -1).astype(np.float32)


def glb(path, mode):
    positions, uvs, indices = sphere()
    base_png, normal_png = textures()
    material = {"pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 1.0}}
    images = []
    if mode == "color":
        material["pbrMetallicRoughness"]["baseColorFactor"] = [0.9, 0.9, 0.9, 1.0]
    elif mode == "base":
        material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
        images.append(base_png)
    else:
        material["pbrMetallicRoughness"]["baseColorFactor"] = [0.8, 0.8, 0.8, 1.0]
        material["normalTexture"] = {"index": 0, "scale": 1.0}
        images.append(normal_png)
    colours = vertex_colours(positions)
    chunks = [positions.tobytes(), positions.tobytes(), uvs.tobytes(), indices.tobytes()] + images
    if mode == "color":
        chunks.append(colours.tobytes())
    blob, views = b"", []
    for data in chunks:
        blob += b"\0" * (-len(blob) % 4)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        blob += data
    blob += b"\0" * (-len(blob) % 4)
    document = {
        "asset": {"version": "2.0", "generator": "iblkit scripts/cross_check"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "materials": [material],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "images": [{"bufferView": 4, "mimeType": "image/png"}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": positions.min(0).tolist(), "max": positions.max(0).tolist()},
            {"bufferView": 1, "componentType": 5126, "count": len(positions), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 3, "componentType": 5125, "count": len(indices), "type": "SCALAR"}],
        "bufferViews": views, "buffers": [{"byteLength": len(blob)}]}
    if mode == "color":  # no texture: the colours' view takes the image's place
        del document["textures"], document["samplers"], document["images"]
        document["accessors"].append({"bufferView": 4, "componentType": 5126, "count": len(colours), "type": "VEC4"})
        document["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 4
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    data = (struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(blob))
            + struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob)
    with open(path, "wb") as f:
        f.write(data)


if __name__ == "__main__":
    path, mode = arguments()[:2]
    glb(path, mode)
