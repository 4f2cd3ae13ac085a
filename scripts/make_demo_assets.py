#!/usr/bin/env python3
"""Builds the demo scene's assets from nothing but maths (so they are ours,
CC0): a trefoil-knot tube as a binary glTF, and a checker texture as PNG.
Run from anywhere; writes into scenes/assets/. Needs only Python 3."""
import json
import math
import struct
import zlib
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "scenes" / "assets"


def trefoil(t):
    # The (2,3) torus knot, scaled to about one unit across.
    x = math.sin(t) + 2 * math.sin(2 * t)
    y = math.cos(t) - 2 * math.cos(2 * t)
    z = -math.sin(3 * t)
    return (x * 0.3, y * 0.3, z * 0.3)


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a):
    n = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
    return (a[0] / n, a[1] / n, a[2] / n)


def knot_mesh(segments=360, sides=32, radius=0.16):
    positions, normals, uvs, indices = [], [], [], []
    # Parallel-transport frames keep the tube from twisting.
    tangents = [norm(sub(trefoil(2 * math.pi * (i + 1) / segments), trefoil(2 * math.pi * (i - 1) / segments)))
                for i in range(segments)]
    normal = norm(cross(tangents[0], (0.0, 0.0, 1.0)))
    frames = []
    for i in range(segments):
        t = tangents[i]
        normal = norm(sub(normal, tuple(t[k] * sum(normal[j] * t[j] for j in range(3)) for k in range(3))))
        frames.append((normal, cross(t, normal)))
    for i in range(segments + 1):
        centre = trefoil(2 * math.pi * (i % segments) / segments)
        n1, n2 = frames[i % segments]
        for j in range(sides + 1):
            a = 2 * math.pi * j / sides
            d = tuple(n1[k] * math.cos(a) + n2[k] * math.sin(a) for k in range(3))
            positions.append(tuple(centre[k] + radius * d[k] for k in range(3)))
            normals.append(d)
            uvs.append((i / segments * 8.0, j / sides))
    row = sides + 1
    for i in range(segments):
        for j in range(sides):
            a, b, c, d = i * row + j, (i + 1) * row + j, (i + 1) * row + j + 1, i * row + j + 1
            indices += [a, d, c, a, c, b]
    return positions, normals, uvs, indices


def check_winding(positions, normals, indices):
    # Outward normals and counter-clockwise faces must agree; flip if not.
    p, n = positions, normals
    a, b, c = indices[0:3]
    face = cross(sub(p[b], p[a]), sub(p[c], p[a]))
    if sum(face[k] * n[a][k] for k in range(3)) < 0:
        for t in range(0, len(indices), 3):
            indices[t + 1], indices[t + 2] = indices[t + 2], indices[t + 1]


def pack_blobs(blobs):
    """One binary buffer holding the blobs, each 4-byte aligned (glTF 2.0
    section 3.6.2.4); returns each blob's offset and the buffer."""
    offsets, data = [], b""
    for blob in blobs:
        offsets.append(len(data))
        data += blob + b"\0" * (-len(blob) % 4)
    return offsets, data


def write_glb_container(path, gltf, data):
    """The binary glTF container: header, JSON chunk, BIN chunk (section 4.4)."""
    js = json.dumps(gltf, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(data), 0x004E4942) + data
    path.write_bytes(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


def write_glb(path, positions, normals, uvs, indices):
    blobs = [b"".join(struct.pack("<3f", *v) for v in positions),
             b"".join(struct.pack("<3f", *v) for v in normals),
             b"".join(struct.pack("<2f", *v) for v in uvs),
             b"".join(struct.pack("<I", i) for i in indices)]
    offsets, data = pack_blobs(blobs)
    lo = [min(v[k] for v in positions) for k in range(3)]
    hi = [max(v[k] for v in positions) for k in range(3)]
    gltf = {
        "asset": {"version": "2.0", "generator": "facet scripts/make_demo_assets.py", "copyright": "CC0 1.0"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "knot"}],
        "meshes": [{"name": "trefoil", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
        "materials": [{"name": "glaze", "pbrMetallicRoughness": {
            "baseColorFactor": [0.9, 0.32, 0.12, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.35}}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": offsets[0], "byteLength": len(blobs[0]), "target": 34962},
            {"buffer": 0, "byteOffset": offsets[1], "byteLength": len(blobs[1]), "target": 34962},
            {"buffer": 0, "byteOffset": offsets[2], "byteLength": len(blobs[2]), "target": 34962},
            {"buffer": 0, "byteOffset": offsets[3], "byteLength": len(blobs[3]), "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 3, "componentType": 5125, "count": len(indices), "type": "SCALAR"}],
    }
    write_glb_container(path, gltf, data)


def tentacle_mesh(rings=48, sides=24, height=1.6, radius=0.16):
    """A tube along +Y that tapers to a rounded tip, skinned to a chain of
    three joints (base, middle, upper) with weights blended by height."""
    positions, normals, joints, weights, indices = [], [], [], [], []
    joint_heights = [0.0, height / 3, 2 * height / 3]
    for i in range(rings + 1):
        y = height * i / rings
        r = radius * (1.0 - 0.75 * (i / rings) ** 1.5)
        # Weights: a linear blend between the two nearest joints.
        seg = min(int(y / (height / 3)), 2)
        f = min(max((y - joint_heights[seg]) / (height / 3), 0.0), 1.0)
        if seg == 2:
            jw = ((2, 0, 0, 0), (1.0, 0.0, 0.0, 0.0))
        else:
            # Smooth the blend so the bend is round, not kinked.
            g = f * f * (3 - 2 * f)
            jw = ((seg, seg + 1, 0, 0), (1.0 - g, g, 0.0, 0.0))
        for j in range(sides + 1):
            a = 2 * math.pi * j / sides
            positions.append((r * math.cos(a), y, -r * math.sin(a)))
            normals.append((math.cos(a), 0.0, -math.sin(a)))
            joints.append(jw[0])
            weights.append(jw[1])
    row = sides + 1
    for i in range(rings):
        for j in range(sides):
            a, b, c, d = i * row + j, i * row + j + 1, (i + 1) * row + j + 1, (i + 1) * row + j
            indices += [a, b, c, a, c, d]
    return positions, normals, joints, weights, indices, joint_heights


def quat_z(degrees):
    h = math.radians(degrees) / 2
    return (0.0, 0.0, math.sin(h), math.cos(h))


def quat_x(degrees):
    h = math.radians(degrees) / 2
    return (math.sin(h), 0.0, 0.0, math.cos(h))


def write_tentacle_glb(path):
    positions, normals, joints, weights, indices, heights = tentacle_mesh()
    check_winding(positions, normals, indices)
    # A 2-second loop: the middle and upper joints sway about Z and X out of
    # phase, so the tip traces a figure of eight. LINEAR rotations (slerp).
    keys = 17
    times = [2.0 * k / (keys - 1) for k in range(keys)]
    sway_mid = [quat_z(28 * math.sin(2 * math.pi * t / 2.0)) for t in times]
    sway_top = []
    for t in times:
        z = quat_z(35 * math.sin(2 * math.pi * t / 2.0 - 0.9))
        x = quat_x(25 * math.sin(4 * math.pi * t / 2.0))
        # q = z * x
        sway_top.append((z[3] * x[0] + z[0] * x[3] + z[1] * x[2] - z[2] * x[1],
                         z[3] * x[1] - z[0] * x[2] + z[1] * x[3] + z[2] * x[0],
                         z[3] * x[2] + z[0] * x[1] - z[1] * x[0] + z[2] * x[3],
                         z[3] * x[3] - z[0] * x[0] - z[1] * x[1] - z[2] * x[2]))
    # Inverse bind matrices: each joint sits at its height on the Y axis.
    def inverse_bind(h):
        return (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -h, 0, 1)  # column-major
    blobs = [b"".join(struct.pack("<3f", *v) for v in positions),
             b"".join(struct.pack("<3f", *v) for v in normals),
             b"".join(struct.pack("<4B", *v) for v in joints),
             b"".join(struct.pack("<4f", *v) for v in weights),
             b"".join(struct.pack("<I", i) for i in indices),
             b"".join(struct.pack("<16f", *inverse_bind(h)) for h in heights),
             b"".join(struct.pack("<f", t) for t in times),
             b"".join(struct.pack("<4f", *q) for q in sway_mid),
             b"".join(struct.pack("<4f", *q) for q in sway_top)]
    offsets, data = pack_blobs(blobs)
    lo = [min(v[k] for v in positions) for k in range(3)]
    hi = [max(v[k] for v in positions) for k in range(3)]
    views = [{"buffer": 0, "byteOffset": offsets[i], "byteLength": len(blobs[i])} for i in range(len(blobs))]
    step = heights[1] - heights[0]
    gltf = {
        "asset": {"version": "2.0", "generator": "facet scripts/make_demo_assets.py", "copyright": "CC0 1.0"},
        "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "tentacle", "mesh": 0, "skin": 0},
            {"name": "base", "children": [2]},
            {"name": "middle", "translation": [0, step, 0], "children": [3]},
            {"name": "upper", "translation": [0, step, 0]}],
        "skins": [{"joints": [1, 2, 3], "inverseBindMatrices": 5, "skeleton": 1}],
        "meshes": [{"name": "tentacle", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "JOINTS_0": 2, "WEIGHTS_0": 3},
            "indices": 4, "material": 0}]}],
        "materials": [{"name": "skin", "pbrMetallicRoughness": {
            "baseColorFactor": [0.2, 0.62, 0.55, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.45}}],
        "animations": [{"name": "sway",
                        "samplers": [{"input": 6, "output": 7, "interpolation": "LINEAR"},
                                     {"input": 6, "output": 8, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}},
                                     {"sampler": 1, "target": {"node": 3, "path": "rotation"}}]}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5121, "count": len(joints), "type": "VEC4"},
            {"bufferView": 3, "componentType": 5126, "count": len(weights), "type": "VEC4"},
            {"bufferView": 4, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
            {"bufferView": 5, "componentType": 5126, "count": len(heights), "type": "MAT4"},
            {"bufferView": 6, "componentType": 5126, "count": len(times), "type": "SCALAR",
             "min": [times[0]], "max": [times[-1]]},
            {"bufferView": 7, "componentType": 5126, "count": len(times), "type": "VEC4"},
            {"bufferView": 8, "componentType": 5126, "count": len(times), "type": "VEC4"}],
    }
    write_glb_container(path, gltf, data)


def write_png(path, width, height, pixel):
    raw = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))
    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    path.write_bytes(png)


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    positions, normals, uvs, indices = knot_mesh()
    check_winding(positions, normals, indices)
    write_glb(OUT / "knot.glb", positions, normals, uvs, indices)
    # 8x8 checker with a soft line between squares, 256x256 pixels.
    def checker(x, y):
        square = ((x // 32) + (y // 32)) % 2
        edge = min(x % 32, y % 32) == 0
        v = 70 if edge else (200 if square else 165)
        return (v, v, v - 8)
    write_png(OUT / "checker.png", 256, 256, checker)
    write_tentacle_glb(OUT / "tentacle.glb")
    # The flag: blue and yellow halves with a white stripe, 192x128 (2:3).
    def flag(x, y):
        if 58 <= y < 70:
            return (240, 240, 236)
        return (20, 80, 180) if y < 64 else (250, 200, 20)
    write_png(OUT / "flag.png", 192, 128, flag)
    print("wrote", OUT / "knot.glb", OUT / "tentacle.glb", "and", OUT / "checker.png", f"({len(indices) // 3} triangles)")


if __name__ == "__main__":
    main()
