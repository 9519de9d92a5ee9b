#!/usr/bin/env python3
"""Regenerates the bad-input glTF corpus in this folder (committed; run by hand after edits).

Each file breaks one rule; tests/core/gltf_load_test.cpp checks the exact error for each, and
that every file in this folder is rejected with an iblkit::Error rather than a crash.
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

TRIANGLE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


def floats(values):
    return b"".join(struct.pack("<3f", *v) for v in values)


def pad4(data, fill=b"\0"):
    return data + fill * (-len(data) % 4)


def document(buffer_bytes, accessors, views, primitive, uri=None, extra=None):
    """A one-mesh, one-node glTF document around the given buffer."""
    buffer = {"byteLength": len(buffer_bytes)}
    if uri is not None:
        buffer["uri"] = uri
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [primitive]}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [buffer],
    }
    doc.update(extra or {})
    return doc


def data_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode("ascii")


def glb(doc, binary):
    text = pad4(json.dumps(doc).encode("utf-8"), b" ")
    binary = pad4(binary)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
    chunks += struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def position_accessor(count, view=0):
    return {"bufferView": view, "componentType": 5126, "count": count, "type": "VEC3"}


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode("utf-8"))


def triangle_gltf(positions, count=3, view_length=None, mode=4, extra=None):
    data = floats(positions)
    view = {"buffer": 0, "byteOffset": 0, "byteLength": len(data) if view_length is None else view_length}
    return document(data, [position_accessor(count)], [view], {"attributes": {"POSITION": 0}, "mode": mode},
                    uri=data_uri(data), extra=extra)


def main():
    # A valid single-triangle .glb cut in half.
    data = floats(TRIANGLE)
    whole = glb(document(data, [position_accessor(3)], [{"buffer": 0, "byteLength": len(data)}],
                         {"attributes": {"POSITION": 0}}), data)
    write("truncated.glb", whole[: len(whole) // 2])

    write("garbage.gltf", "this is not a glTF file {\n")

    # 3 positions in the buffer, an accessor claiming 12.
    write("accessor_past_buffer.gltf", json.dumps(triangle_gltf(TRIANGLE, count=12)))

    # A buffer view longer than its buffer.
    write("buffer_view_past_buffer.gltf", json.dumps(triangle_gltf(TRIANGLE, view_length=64)))

    # Index 57 into 3 vertices.
    positions = floats(TRIANGLE)
    indices = struct.pack("<3H", 0, 1, 57)
    data = positions + pad4(indices)
    write("index_out_of_range.gltf", json.dumps(document(
        data,
        [position_accessor(3), {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        [{"buffer": 0, "byteLength": len(positions)},
         {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        {"attributes": {"POSITION": 0}, "indices": 1}, uri=data_uri(data))))

    # An external buffer outside the file's folder.
    data = floats(TRIANGLE)
    write("uri_outside_folder.gltf", json.dumps(document(
        data, [position_accessor(3)], [{"buffer": 0, "byteLength": len(data)}],
        {"attributes": {"POSITION": 0}}, uri="../secret.bin")))

    # An external buffer that does not exist.
    write("missing_bin.gltf", json.dumps(document(
        data, [position_accessor(3)], [{"buffer": 0, "byteLength": len(data)}],
        {"attributes": {"POSITION": 0}}, uri="missing.bin")))

    # A Draco primitive whose compressed stream is a plausible header followed by junk.
    stream = b"DRACO" + bytes([2, 2, 1, 1, 0, 0]) + b"\xff" * 21
    draco = {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}
    write("bad_draco.glb", glb(document(
        stream,
        [{"componentType": 5126, "count": 3, "type": "VEC3"},
         {"componentType": 5123, "count": 3, "type": "SCALAR"}],
        [{"buffer": 0, "byteLength": len(stream)}],
        {"attributes": {"POSITION": 0}, "indices": 1, "extensions": draco},
        extra={"extensionsUsed": ["KHR_draco_mesh_compression"],
               "extensionsRequired": ["KHR_draco_mesh_compression"]}), stream))

    # NaN in a position.
    write("nan_position.gltf", json.dumps(triangle_gltf([(0.0, 0.0, 0.0), (math.nan, 0.0, 0.0), (0.0, 1.0, 0.0)])))

    # Only points.
    write("points_only.gltf", json.dumps(triangle_gltf(TRIANGLE, mode=0)))

    # Node 0 is its own grandchild: a cycle that a recursive traversal would never leave.
    write("node_cycle.gltf", json.dumps(triangle_gltf(
        TRIANGLE, extra={"nodes": [{"mesh": 0, "children": [1]}, {"children": [0]}]})))

    # A required extension iblkit does not implement.
    write("unsupported_extension.gltf", json.dumps(triangle_gltf(
        TRIANGLE, extra={"extensionsUsed": ["EXT_texture_avif"],
                         "extensionsRequired": ["EXT_texture_avif"]})))


if __name__ == "__main__":
    main()
