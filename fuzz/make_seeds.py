#!/usr/bin/env python3
"""Regenerates the hand-made seeds of the fuzz corpora, fuzz/corpus/<target>/seed_* (committed; run
by hand after edits). Small valid inputs of each format, so the fuzzer starts from files that get
past the first checks. One seed is not made here: fuzz/corpus/gltf/seed_meshopt.glb is the file of
tests/core/gltf_meshopt_test.cpp's first test (compressed by meshoptimizer's encoders, which Python
does not have), copied by hand. The other seeds (tests/data, assets/) are picked up by scripts/fuzz.sh at
run time; the findings (fuzz/corpus/<target>/finding_*) are added by hand, one per finding.
"""
import base64
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def put(target, name, data):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


# --- Radiance .hdr -------------------------------------------------------------------------------
def rgbe(r, g, b):
    import math
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    mant, e = math.frexp(m)
    scale = mant * 256.0 / m
    return bytes([int(r * scale), int(g * scale), int(b * scale), e + 128])


def hdr_flat(width, height, extra=""):
    head = "#?RADIANCE\n" + extra + "FORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width)
    pixels = b"".join(rgbe(0.1 * x + 0.05, 0.5, 1.0 + y) for y in range(height) for x in range(width))
    return head.encode() + pixels


def hdr_rle(width, height):
    head = ("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width)).encode()
    body = b""
    for y in range(height):
        body += bytes([2, 2, width >> 8, width & 255])
        row = [rgbe(0.25 + 0.01 * x, 0.5, 2.0) for x in range(width)]
        for c in range(4):
            values = bytes(p[c] for p in row)
            half = width // 2
            body += bytes([128 + half, values[0]])           # a run
            body += bytes([width - half]) + values[half:]    # literals
    return head + body


put("hdr", "seed_flat_4x2.hdr", hdr_flat(4, 2, "EXPOSURE=1.0\n"))
put("hdr", "seed_rle_16x2.hdr", hdr_rle(16, 2))


# --- PNG ---------------------------------------------------------------------------------------
def png(width, height, color_type, channels, depth=8):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b""
    for y in range(height):
        raw += b"\0" + bytes((17 * (x + y + c)) & 255 for x in range(width) for c in range(channels))
    ihdr = struct.pack(">IIBBBBB", width, height, depth, color_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


put("png", "seed_rgb_3x2.png", png(3, 2, 2, 3))
put("png", "seed_rgba_2x2.png", png(2, 2, 6, 4))
put("png", "seed_grey_2x1.png", png(2, 1, 0, 1))


# --- OpenEXR (uncompressed half RGB: one scanline file, one tiled mip-mapped file) ---------------
def attribute(name, kind, data):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data


def header(width, height, extra=b""):
    channels = b"".join(c + b"\0" + struct.pack("<iBBBBii", 1, 0, 0, 0, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    return (attribute("channels", "chlist", channels) + attribute("compression", "compression", b"\0")
            + attribute("dataWindow", "box2i", box) + attribute("displayWindow", "box2i", box)
            + attribute("lineOrder", "lineOrder", b"\0") + attribute("pixelAspectRatio", "float", struct.pack("<f", 1))
            + attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0))
            + attribute("screenWindowWidth", "float", struct.pack("<f", 1)) + extra + b"\0")


def half_row(width, value):
    return b"".join(struct.pack("<e", value + 0.125 * x) for x in range(width))


def exr_scanline(width, height, envmap=None):
    extra = attribute("envmap", "envmap", bytes([envmap])) if envmap is not None else b""
    extra += attribute("owner", "string", b"iblkit fuzz seed")
    head = struct.pack("<ii", 20000630, 2) + header(width, height, extra)
    chunks = []
    for y in range(height):
        data = b"".join(half_row(width, v + y) for v in (0.25, 0.5, 1.0))
        chunks.append(struct.pack("<ii", y, len(data)) + data)
    offset = len(head) + 8 * height
    table = b""
    for c in chunks:
        table += struct.pack("<Q", offset)
        offset += len(c)
    return head + table + b"".join(chunks)


def exr_tiled_mip(size):
    # MIPMAP_LEVELS, ROUND_DOWN; one tile per level (tile size = level 0 size).
    extra = attribute("tiles", "tiledesc", struct.pack("<IIB", size, size, 1))
    head = struct.pack("<ii", 20000630, 2 | 0x200) + header(size, size, extra)
    levels = []
    s = size
    while s >= 1:
        levels.append(s)
        s //= 2
    chunks = []
    for level, s in enumerate(levels):
        data = b"".join(half_row(s, v + y) for y in range(s) for v in (0.25, 0.5, 1.0))
        chunks.append(struct.pack("<iiiii", 0, 0, level, level, len(data)) + data)
    offset = len(head) + 8 * len(chunks)
    table = b""
    for c in chunks:
        table += struct.pack("<Q", offset)
        offset += len(c)
    return head + table + b"".join(chunks)


put("exr", "seed_scanline_4x2.exr", exr_scanline(4, 2, envmap=0))
put("exr", "seed_cube_2x12.exr", exr_scanline(2, 12, envmap=1))
put("exr", "seed_tiled_mip_4.exr", exr_tiled_mip(4))


# --- glTF / glb --------------------------------------------------------------------------------
def triangle_gltf(embed=True, mode=4):
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    normals = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
    indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    buffer = positions + normals + indices
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "translation": [0, 0.5, 0], "scale": [2, 2, 2], "children": [2]},
                  {"camera": 0, "translation": [0, 0, 3]},
                  {"mesh": 0, "rotation": [0, 0.7071, 0, 0.7071]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "aspectRatio": 1.5}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "mode": mode,
                                    "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1], "metallicFactor": 0.5,
                                                "roughnessFactor": 0.3},
                       "emissiveFactor": [0, 0, 0],
                       "extensions": {"KHR_materials_specular": {"specularFactor": 0.5},
                                      "KHR_materials_emissive_strength": {"emissiveStrength": 2}}}],
        "extensionsUsed": ["KHR_materials_specular", "KHR_materials_emissive_strength"],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 72, "byteLength": 6}],
        "buffers": [{"byteLength": len(buffer)}],
    }
    if embed:
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()
    return doc, buffer


def glb(doc, buffer):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    buffer += b"\0" * (-len(buffer) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(buffer), b"BIN\0") + buffer
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


doc, _ = triangle_gltf()
put("gltf", "seed_triangle.gltf", json.dumps(doc, indent=1))
doc, _ = triangle_gltf(mode=5)
put("gltf", "seed_strip.gltf", json.dumps(doc))
doc, buffer = triangle_gltf(embed=False)
put("gltf", "seed_triangle.glb", glb(doc, buffer))


class Triangle:
    """triangle_gltf's document and buffer 0, with data appended as 4-byte aligned buffer views and
    accessors; glb() or gltf() writes it with the buffer's final length."""

    def __init__(self):
        self.doc, self.buffer = triangle_gltf(embed=False)

    def view(self, data, **extra):
        self.buffer += b"\0" * (-len(self.buffer) % 4)
        self.doc["bufferViews"].append(dict({"buffer": 0, "byteOffset": len(self.buffer), "byteLength": len(data)},
                                            **extra))
        self.buffer += data
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, data, count, kind, component=5126, **extra):
        self.doc["accessors"].append(dict({"bufferView": self.view(data), "componentType": component, "count": count,
                                           "type": kind}, **extra))
        return len(self.doc["accessors"]) - 1

    def glb(self):
        self.doc["buffers"][0]["byteLength"] = len(self.buffer)
        return glb(self.doc, self.buffer)

    def gltf(self):
        self.doc["buffers"][0]["byteLength"] = len(self.buffer)
        self.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(self.buffer).decode()
        return json.dumps(self.doc)


def textured_glb():
    """The triangle with TEXCOORD_0, TEXCOORD_1 and TANGENT, a PNG in the glb's buffer and a WebP
    (EXT_texture_webp; the lossless seed of fuzz/corpus/texture, made by make_texture_seeds) as a
    data: URI, two samplers, and every texture slot, KHR_texture_transform and alpha mode used."""
    t = Triangle()
    doc = t.doc
    primitive = doc["meshes"][0]["primitives"][0]
    primitive["attributes"]["TEXCOORD_0"] = t.accessor(struct.pack("<6f", 0, 0, 1, 0, 0, 1), 3, "VEC2")
    primitive["attributes"]["TEXCOORD_1"] = t.accessor(struct.pack("<6f", 0, 1, 1, 1, 0, 0), 3, "VEC2")
    primitive["attributes"]["TANGENT"] = t.accessor(struct.pack("<12f", *([1, 0, 0, 1] * 3)), 3, "VEC4")
    with open(os.path.join(HERE, "corpus", "texture", "seed_rgba_lossless_4x4.webp"), "rb") as f:
        webp = f.read()
    doc["images"] = [{"bufferView": t.view(png(2, 2, 6, 4)), "mimeType": "image/png", "name": "albedo"},
                     {"uri": "data:image/webp;base64," + base64.b64encode(webp).decode()}]
    doc["samplers"] = [{"magFilter": 9728, "minFilter": 9986, "wrapS": 33071, "wrapT": 33648}, {}]
    doc["textures"] = [{"source": 0, "sampler": 0},
                       {"source": 0, "sampler": 1, "extensions": {"EXT_texture_webp": {"source": 1}}}]
    material = doc["materials"][0]
    transform = {"KHR_texture_transform": {"offset": [0.5, 0], "rotation": 0.3, "scale": [2, 2], "texCoord": 1}}
    material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0, "extensions": transform}
    material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {"index": 1, "texCoord": 1}
    material["normalTexture"] = {"index": 1, "scale": 0.5}
    material["occlusionTexture"] = {"index": 0, "strength": 0.8}
    material["emissiveTexture"] = {"index": 1}
    material["alphaMode"] = "MASK"
    material["alphaCutoff"] = 0.4
    material["doubleSided"] = True
    doc["extensionsUsed"] += ["KHR_texture_transform", "EXT_texture_webp"]
    doc["extensionsRequired"] = ["KHR_texture_transform", "EXT_texture_webp"]
    return t.glb()


put("gltf", "seed_textured.glb", textured_glb())


def coloured_glb():
    """The triangle with COLOR_0 as normalised unsigned bytes (VEC4, alpha below 1 on one corner)
    and a BLEND material, so that the fuzzer reaches the vertex colours' reader."""
    t = Triangle()
    colours = struct.pack("<12B", 255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255)
    t.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = t.accessor(colours, 3, "VEC4", 5121, normalized=True)
    t.doc["materials"][0]["alphaMode"] = "BLEND"
    return t.glb()


put("gltf", "seed_colors.glb", coloured_glb())


def sparse_glb():
    """The triangle with a sparse POSITION (vertex 1 moved) and a sparse custom attribute without a
    buffer view (zeros, two elements replaced), so that the fuzzer reaches the sparse reader."""
    t = Triangle()
    doc = t.doc
    doc["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": t.view(struct.pack("<H", 1)), "componentType": 5123},
                                     "values": {"bufferView": t.view(struct.pack("<3f", 2, 0, 0))}}
    doc["accessors"][0]["max"] = [2, 1, 0]
    doc["accessors"].append({"componentType": 5126, "count": 3, "type": "SCALAR",
                             "sparse": {"count": 2, "indices": {"bufferView": t.view(bytes([0, 2])), "componentType": 5121},
                                        "values": {"bufferView": t.view(struct.pack("<2f", 0.25, 0.75))}}})
    doc["meshes"][0]["primitives"][0]["attributes"]["_W"] = len(doc["accessors"]) - 1
    return t.glb()


put("gltf", "seed_sparse.glb", sparse_glb())


def skinned_glb():
    """The triangle skinned to two joints (one with an inverse bind matrix) and with a morph target
    at weight 0.5, so that the fuzzer reaches the static pose's readers."""
    t = Triangle()
    doc = t.doc
    attributes = doc["meshes"][0]["primitives"][0]["attributes"]
    attributes["JOINTS_0"] = t.accessor(bytes([0, 1, 0, 0] * 3), 3, "VEC4", 5121)
    attributes["WEIGHTS_0"] = t.accessor(struct.pack("<12f", 1, 0, 0, 0, 0.5, 0.5, 0, 0, 0, 1, 0, 0), 3, "VEC4")
    doc["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": t.accessor(struct.pack("<9f", 0, 0, 0, 0, 0, 1, 0, 0, 0), 3, "VEC3")}]
    doc["meshes"][0]["weights"] = [0.5]
    identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    moved = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]
    matrices = t.accessor(struct.pack("<32f", *identity, *moved), 2, "MAT4")
    doc["nodes"] += [{"translation": [0, 0, 1]}, {"translation": [0, 1, 0], "rotation": [0, 0.7071, 0, 0.7071]}]
    doc["nodes"][0]["skin"] = 0
    doc["nodes"][0]["children"] += [3, 4]
    doc["skins"] = [{"joints": [3, 4], "inverseBindMatrices": matrices}]
    return t.glb()


put("gltf", "seed_skinned.glb", skinned_glb())


def instanced_gltf():
    """The triangle drawn three times by EXT_mesh_gpu_instancing (translations, rotations, scales),
    with a KHR_lights_punctual light, so that the fuzzer reaches the instance reader."""
    t = Triangle()
    doc = t.doc
    translations = t.accessor(struct.pack("<9f", 0, 0, 0, 1, 0, 0, 2, 0, 0), 3, "VEC3")
    rotations = t.accessor(struct.pack("<12f", 0, 0, 0, 1, 0, 0.7071, 0, 0.7071, 0, 1, 0, 0), 3, "VEC4")
    scales = t.accessor(struct.pack("<9f", 1, 1, 1, 2, 2, 2, 0.5, 0.5, 0.5), 3, "VEC3")
    doc["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {
        "attributes": {"TRANSLATION": translations, "ROTATION": rotations, "SCALE": scales}}}
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3}]}}
    doc["extensionsUsed"] += ["EXT_mesh_gpu_instancing", "KHR_lights_punctual"]
    return t.gltf()


put("gltf", "seed_instanced.gltf", instanced_gltf())


def specular_glossiness_glb():
    """The triangle with a KHR_materials_pbrSpecularGlossiness material (every factor, a diffuse
    texture), so that the fuzzer reaches its conversion."""
    t = Triangle()
    primitive = t.doc["meshes"][0]["primitives"][0]
    primitive["attributes"]["TEXCOORD_0"] = t.accessor(struct.pack("<6f", 0, 0, 1, 0, 0, 1), 3, "VEC2")
    t.doc["images"] = [{"bufferView": t.view(png(2, 2, 6, 4)), "mimeType": "image/png"}]
    t.doc["textures"] = [{"source": 0}]
    t.doc["materials"] = [{"extensions": {"KHR_materials_pbrSpecularGlossiness": {
        "diffuseFactor": [0.5, 0.25, 1, 0.8], "specularFactor": [0.04, 0.02, 0.5], "glossinessFactor": 0.75,
        "diffuseTexture": {"index": 0}, "specularGlossinessTexture": {"index": 0}}}}]
    t.doc["extensionsUsed"] = ["KHR_materials_pbrSpecularGlossiness"]
    return t.glb()


put("gltf", "seed_specular_glossiness.glb", specular_glossiness_glb())

# --- scene .json (fuzz_loaders.cpp puts model.gltf and env.hdr beside the scene) ---------------
put("scene", "seed_textured.json", json.dumps({
    "models": [{"file": "model.gltf", "material": {
        "alphaMode": "BLEND", "alpha": 0.5, "doubleSided": True,
        "normalTexture": {"file": "albedo.png", "scale": 0.5, "uvScale": [4, 2], "texCoord": 1},
        "baseColorTexture": {"file": "albedo.png"}}}],
    "ground": {"material": {"alphaMode": "MASK", "alphaCutoff": 0.2,
                            "occlusionTexture": {"file": "albedo.png", "strength": 0.5, "uvScale": 3}}}}))
put("scene", "seed_shapes.json", json.dumps({
    "models": [{"shape": "sphere", "translation": [0, 1, 0], "rotation": [0, 0.2588, 0, 0.9659], "scale": 0.5,
                "material": {"baseColor": [0.9, 0.1, 0.1], "metallic": 1, "roughness": 0.2}},
               {"file": "model.gltf", "scale": [1, 2, 1], "material": {"emissive": [1, 1, 1],
                                                                       "specularColor": [1, 1, 1]}}],
    "ground": {"enabled": True, "height": 0, "size": 4, "material": {"specular": 0.5}},
    "environment": {"file": "env.hdr", "rotation": 90, "intensity": 2},
    "camera": {"position": [0, 1, 4], "target": [0, 0.5, 0], "up": [0, 1, 0], "yfov": 40, "znear": 0.1, "zfar": 100},
    "width": 64, "height": 32}, indent=1))

# --- bake.json and sh9.json --------------------------------------------------------------------
put("bake_record", "seed_bake.json", json.dumps({
    "version": "iblkit-bake 1",
    "inputs": {"scene": "/x/scene.json", "environment": "env.exr"},
    "parameters": {"environment_rotation_degrees": 90.0, "environment_intensity": 1.5, "env_format": "latlong",
                   "samples": 256},
    "timings": {"total_s": 1.5}}, indent=1))
put("bake_record", "seed_bake_no_env.json", json.dumps({
    "version": "iblkit-bake 1", "inputs": {"scene": "scene.json", "environment": None}, "parameters": {}}))
sh9 = [[0.1 * k, 0.2, 0.3 - 0.01 * k] for k in range(9)]
light = {"direction": [0.6, 0.8, 0.0], "irradiance": [5.5, 5.6, 5.1], "radiance": [8169.2, 8232.3, 7565.7],
         "solidAngle": 0.00068, "angularRadius": 0.0147, "texels": [299, 55, 310, 64], "sh9": sh9}
put("lights", "seed_lights.json", json.dumps({
    "kind": "iblkit environment lights", "units": "...", "sunThreshold": 21.8, "medianCutLevels": 1,
    "suns": [light], "medianCut": [dict(light, texels=[0, 0, 256, 256]), dict(light, texels=[256, 0, 512, 256])]},
    indent=1))
put("sh9", "seed_sh9.json", json.dumps({
    "basis": "real, orthonormal", "A": [3.14159, 2.0944, 0.785398],
    "L": [[0.1 * k, 0.2, 0.3 - 0.01 * k] for k in range(9)], "windowCutoff": 22.75}, indent=1))

# --- reference pass sums (reference/pass_sum.h) ----------------------------------------------------
def fnv1a_length_prefixed(data):
    """ContentHash().add(data).value(): FNV-1a 64 of the length (8 bytes, little-endian), then the bytes."""
    h = 0xcbf29ce484222325
    for byte in struct.pack("<Q", len(data)) + data:
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def pass_sum(width, height, ranges, key=0x1234):
    count = sum(c for _, c in ranges)
    head = b"IBLKSUM\n" + struct.pack("<IIIIII", 1, width, height, 6, 32, len(ranges)) + struct.pack("<QQ", key, count)
    head += b"".join(struct.pack("<II", first, c) for first, c in ranges)
    body = b""
    for p in range(width * height):
        value = (p + 1) * count << 31  # mean radiance (p + 1) / 2 per channel
        body += b"".join(struct.pack("<q", value).ljust(16, b"\0" if value >= 0 else b"\xff") for _ in range(3))
        body += b"".join(struct.pack("<Q", value * (p + 1) // 2 & 0xFFFFFFFFFFFFFFFF) + struct.pack("<Q", 0)
                         for _ in range(3))
    data = head + body
    return data + struct.pack("<Q", fnv1a_length_prefixed(data))


put("pass_sum", "seed_2x1_one_range.sum", pass_sum(2, 1, [(0, 4)]))
put("pass_sum", "seed_1x2_two_ranges.sum", pass_sum(1, 2, [(0, 2), (8, 3)]))
