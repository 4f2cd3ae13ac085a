#!/usr/bin/env python3
"""Builds the demo scenes' assets from nothing but maths (so they are ours,
CC0): a trefoil-knot tube and a skinned tentacle as binary glTF, checker and
flag textures as PNG, and the PBR sampler (spheres across roughness, metal
and dielectric, a normal-mapped panel with its occlusion map, a part with a
metal-rough map) as binary glTF with its textures inside.
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


def png_bytes(width, height, pixel, up_filter=False):
    """An 8-bit RGB PNG of pixel(x, y). With up_filter, each row is stored as
    its difference from the row above (PNG filter type 2), which makes smooth
    images such as normal maps several times smaller."""
    rows = [b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height)]
    if up_filter:
        above = [bytes(len(rows[0]))] + rows[:-1]
        raw = b"".join(b"\2" + bytes((a - b) & 255 for a, b in zip(row, prev)) for row, prev in zip(rows, above))
    else:
        raw = b"".join(b"\0" + row for row in rows)
    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    return png + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def write_png(path, width, height, pixel):
    path.write_bytes(png_bytes(width, height, pixel))


# The PBR sampler (scenes/assets/pbr_sampler.glb, shown by scenes/pbr.yaml):
# the inputs of glTF's metallic-roughness material, each on its own part.

SAMPLER_ROUGHNESS = (0.05, 0.25, 0.5, 0.75, 1.0)
RED_PLASTIC = [0.8, 0.08, 0.05, 1.0]  # linear base colours
GOLD = [1.0, 0.78, 0.34, 1.0]
COPPER = [0.95, 0.64, 0.54, 1.0]
BUMP_CELLS = 4      # the panel's pattern: 4 x 4 hemispherical bumps
BUMP_RADIUS = 0.38  # in cells


def f32(x):
    """x as the float32 the file stores, so that min and max match the data."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def uv_sphere(radius, segments=48, rings=24):
    """A sphere about the origin, +Y up; u runs once round (rightward seen
    from outside), v from the top pole (0) to the bottom (1)."""
    positions, normals, uvs, indices = [], [], [], []
    for i in range(rings + 1):
        polar = math.pi * i / rings
        for j in range(segments + 1):
            azimuth = 2 * math.pi * j / segments
            n = (math.sin(polar) * math.cos(azimuth), math.cos(polar), -math.sin(polar) * math.sin(azimuth))
            if i in (0, rings):
                n = (0.0, 1.0 if i == 0 else -1.0, 0.0)  # exactly the pole, for every u
            positions.append(tuple(radius * c for c in n))
            normals.append(n)
            uvs.append((j / segments, i / rings))
    row = segments + 1
    for i in range(rings):
        for j in range(segments):
            a, b, c, d = i * row + j, (i + 1) * row + j, (i + 1) * row + j + 1, i * row + j + 1
            # The quads at the poles are triangles: skip the one of zero area.
            if i > 0:
                indices += [a, c, d]
            if i < rings - 1:
                indices += [a, b, c]
    return positions, normals, uvs, indices


def panel(size, cells=8):
    """A square in the XY plane facing +Z, centred on the origin, its texture
    upright (v = 0 at the top edge); tangents along +u (+X) with w = +1, so
    the bitangent w (n x t) is +Y, up the texture, as glTF's normal maps want."""
    positions, uvs, indices = [], [], []
    for i in range(cells + 1):
        for j in range(cells + 1):
            u, v = j / cells, i / cells
            positions.append(((u - 0.5) * size, (0.5 - v) * size, 0.0))
            uvs.append((u, v))
    row = cells + 1
    for i in range(cells):
        for j in range(cells):
            a, b, c, d = i * row + j, (i + 1) * row + j, (i + 1) * row + j + 1, i * row + j + 1
            indices += [a, b, c, a, c, d]
    count = len(positions)
    return positions, [(0.0, 0.0, 1.0)] * count, uvs, [(1.0, 0.0, 0.0, 1.0)] * count, indices


def bump_normal(x, y):
    """The unit normal at (x, y) of one cell of the pattern, in cell units
    from the cell's centre with y up: a hemisphere of BUMP_RADIUS on a plane."""
    r2 = BUMP_RADIUS * BUMP_RADIUS
    d2 = x * x + y * y
    if d2 >= r2:
        return (0.0, 0.0, 1.0)
    return (x / BUMP_RADIUS, y / BUMP_RADIUS, math.sqrt(r2 - d2) / BUMP_RADIUS)


def tiled(size, cell_value):
    """pixel(x, y) for a texture of BUMP_CELLS x BUMP_CELLS identical cells,
    each computed once; cell_value(px, py, n) gets the texel in its cell."""
    n = size // BUMP_CELLS
    cache = {}
    def pixel(x, y):
        key = (x % n, y % n)
        if key not in cache:
            cache[key] = cell_value(key[0], key[1], n)
        return cache[key]
    return pixel


def normal_texel(px, py, n, sub=4):
    """Tangent-space normal of a texel (+X right, +Y up the image, as glTF
    has it), averaged over sub x sub points so the bumps' rims are smooth."""
    total = [0.0, 0.0, 0.0]
    for i in range(sub):
        for j in range(sub):
            x = (px + (i + 0.5) / sub) / n - 0.5
            y = 0.5 - (py + (j + 0.5) / sub) / n  # image rows go down, +Y goes up
            nx, ny, nz = bump_normal(x, y)
            total = [total[0] + nx, total[1] + ny, total[2] + nz]
    length = math.sqrt(sum(c * c for c in total))
    return tuple(round((c / length + 1) * 127.5) for c in total)


def cosine_directions(k=16):
    """k x k directions over the hemisphere about +Z, stratified and
    distributed as the cosine, so that the fraction of them that escape is
    the occlusion texture's value (the visible sky, cosine-weighted)."""
    dirs = []
    for a in range(k):
        for b in range(k):
            r2, phi = (a + 0.5) / k, 2 * math.pi * (b + 0.5) / k
            r = math.sqrt(r2)
            dirs.append((r * math.cos(phi), r * math.sin(phi), math.sqrt(1 - r2)))
    return dirs


def turn_z_to(n, d):
    """d rotated by the rotation that takes +Z to the unit vector n (about
    the axis z x n), which varies smoothly with n over the bumps."""
    c = n[2]
    if c > 1 - 1e-12:
        return d
    ax, ay = -n[1], n[0]  # z x n, of length sin
    s2 = ax * ax + ay * ay
    k = (1 - c) / s2
    dot = ax * d[0] + ay * d[1]
    # Rodrigues: d c + (a x d) + a (a . d) (1 - c) / sin^2, with a = z x n.
    return (d[0] * c + ay * d[2] + ax * dot * k,
            d[1] * c - ax * d[2] + ay * dot * k,
            d[2] * c + ax * d[1] - ay * d[0])


def occlusion_texel(px, py, n, directions):
    """The cosine-weighted fraction of the sky a point of the pattern sees,
    computed from the exact shapes: the ground plane and the hemispheres of
    this cell and the 24 around it (the pattern taken as repeating)."""
    x, y = (px + 0.5) / n - 0.5, 0.5 - (py + 0.5) / n
    normal = bump_normal(x, y)
    height = normal[2] * BUMP_RADIUS if x * x + y * y < BUMP_RADIUS ** 2 else 0.0
    origin = (x + 1e-6 * normal[0], y + 1e-6 * normal[1], height + 1e-6 * normal[2])
    centres = [(i, j) for i in range(-2, 3) for j in range(-2, 3)]
    seen = 0
    for d in directions:
        w = turn_z_to(normal, d)
        if w[2] < 0:
            continue  # toward the ground
        hit = False
        for cx, cy in centres:
            ox, oy, oz = origin[0] - cx, origin[1] - cy, origin[2]
            b = ox * w[0] + oy * w[1] + oz * w[2]
            c = ox * ox + oy * oy + oz * oz - BUMP_RADIUS ** 2
            if b < 0 and b * b > c:
                hit = True
                break
        seen += not hit
    v = round(255 * seen / len(directions))
    return (v, v, v)


def metal_rough_texel(x, y, width, height):
    """Eight bands across u, metal (B = 1) and dielectric (B = 0) in turn;
    roughness (G) rising from 0.05 at the top to 1 at the bottom. R is 1, so
    a reader that takes R for occlusion sees none."""
    metal = 255 if (x * 8 // width) % 2 == 0 else 0
    roughness = 0.05 + 0.95 * (y + 0.5) / height
    return (255, round(255 * roughness), metal)


class GlbBuilder:
    """Buffer views and accessors for one binary glTF, in the order added."""

    def __init__(self):
        self.blobs, self.views, self.accessors = [], [], []

    def view(self, blob, target=None):
        self.blobs.append(blob)
        self.views.append({"buffer": 0, "byteLength": len(blob)})
        if target:
            self.views[-1]["target"] = target
        return len(self.views) - 1

    def floats(self, values, kind, bounds=False):
        values = [tuple(f32(c) for c in v) for v in values]
        width = len(values[0])
        blob = b"".join(struct.pack("<%df" % width, *v) for v in values)
        accessor = {"bufferView": self.view(blob, 34962), "componentType": 5126,
                    "count": len(values), "type": kind}
        if bounds:
            accessor["min"] = [min(v[k] for v in values) for k in range(width)]
            accessor["max"] = [max(v[k] for v in values) for k in range(width)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def indices(self, values):
        blob = b"".join(struct.pack("<H", i) for i in values)
        self.accessors.append({"bufferView": self.view(blob, 34963), "componentType": 5123,
                               "count": len(values), "type": "SCALAR"})
        return len(self.accessors) - 1

    def write(self, path, gltf):
        offsets, data = pack_blobs(self.blobs)
        for view, offset in zip(self.views, offsets):
            view["byteOffset"] = offset
        gltf.update({"buffers": [{"byteLength": len(data)}], "bufferViews": self.views,
                     "accessors": self.accessors})
        write_glb_container(path, gltf, data)


def sphere_attributes(glb, radius, textured):
    positions, normals, uvs, indices = uv_sphere(radius)
    check_winding(positions, normals, indices)
    attributes = {"POSITION": glb.floats(positions, "VEC3", bounds=True), "NORMAL": glb.floats(normals, "VEC3")}
    if textured:
        attributes["TEXCOORD_0"] = glb.floats(uvs, "VEC2")
    return attributes, glb.indices(indices)


def sampler_materials():
    """Materials 0-4 red plastic and 5-9 gold at each roughness, 10 the
    bumped panel (textures 0 normal, 1 occlusion), 11 the banded part
    (texture 2, metal-rough)."""
    materials = []
    for name, colour, metal in (("plastic", RED_PLASTIC, 0.0), ("gold", GOLD, 1.0)):
        for r in SAMPLER_ROUGHNESS:
            materials.append({"name": f"{name} roughness {r}", "pbrMetallicRoughness": {
                "baseColorFactor": colour, "metallicFactor": metal, "roughnessFactor": r}})
    materials.append({"name": "bumps", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.8, 0.78, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.45},
        "normalTexture": {"index": 0, "scale": 1.0}, "occlusionTexture": {"index": 1, "strength": 1.0}})
    materials.append({"name": "metal and dielectric bands", "pbrMetallicRoughness": {
        "baseColorFactor": COPPER, "metallicFactor": 1.0, "roughnessFactor": 1.0,
        "metallicRoughnessTexture": {"index": 2}}})
    return materials


def write_pbr_sampler(path):
    glb = GlbBuilder()
    small, small_indices = sphere_attributes(glb, 0.16, textured=False)
    large, large_indices = sphere_attributes(glb, 0.3, textured=True)
    positions, normals, uvs, tangents, indices = panel(0.7)
    flat = {"POSITION": glb.floats(positions, "VEC3", bounds=True), "NORMAL": glb.floats(normals, "VEC3"),
            "TEXCOORD_0": glb.floats(uvs, "VEC2")}
    with_tangents = dict(flat, TANGENT=glb.floats(tangents, "VEC4"))
    panel_indices = glb.indices(indices)
    directions = cosine_directions()
    images = [png_bytes(256, 256, tiled(256, normal_texel), up_filter=True),
              png_bytes(128, 128, tiled(128, lambda x, y, n: occlusion_texel(x, y, n, directions)),
                        up_filter=True),
              png_bytes(128, 64, lambda x, y: metal_rough_texel(x, y, 128, 64), up_filter=True)]
    image_views = [glb.view(png) for png in images]
    meshes, nodes = [], []
    # Two rows of five spheres resting on y = 0: plastic in front, gold behind.
    for m in range(10):
        meshes.append({"name": sampler_materials()[m]["name"],
                       "primitives": [{"attributes": small, "indices": small_indices, "material": m}]})
        nodes.append({"name": meshes[-1]["name"], "mesh": m,
                      "translation": [-0.84 + 0.42 * (m % 5), 0.16, 0.35 if m < 5 else -0.05]})
    # Behind them, standing: the bumped panel with its tangents (left), the
    # same panel without them (right), and the banded sphere between.
    meshes.append({"name": "bumps, file tangents", "primitives": [
        {"attributes": with_tangents, "indices": panel_indices, "material": 10}]})
    meshes.append({"name": "bumps, generated tangents", "primitives": [
        {"attributes": flat, "indices": panel_indices, "material": 10}]})
    meshes.append({"name": "metal and dielectric bands", "primitives": [
        {"attributes": large, "indices": large_indices, "material": 11}]})
    for mesh, translation in ((10, [-0.75, 0.35, -0.55]), (11, [0.75, 0.35, -0.55]), (12, [0.0, 0.3, -0.55])):
        nodes.append({"name": meshes[mesh]["name"], "mesh": mesh, "translation": translation})
    sampler = {"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}
    gltf = {
        "asset": {"version": "2.0", "generator": "facet scripts/make_demo_assets.py", "copyright": "CC0 1.0"},
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes, "meshes": meshes, "materials": sampler_materials(),
        "samplers": [sampler],
        "images": [{"bufferView": v, "mimeType": "image/png"} for v in image_views],
        "textures": [{"sampler": 0, "source": i} for i in range(len(images))],
    }
    glb.write(path, gltf)


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
    write_pbr_sampler(OUT / "pbr_sampler.glb")
    print("wrote", OUT / "knot.glb", OUT / "tentacle.glb", OUT / "pbr_sampler.glb", "and", OUT / "checker.png",
          f"({len(indices) // 3} triangles in the knot)")


if __name__ == "__main__":
    main()
