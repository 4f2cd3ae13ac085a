#!/usr/bin/env python3
"""Writes the small hand-made seed files of tests/fuzz/corpus (OBJ, glTF,
PNG, a manifest and a run journal, -D lines for
tests/scenes/fuzz_overridden.yaml). The scene seeds are copies of scenes/ and styles/ files; fuzz.sh adds
the installed assimp test models as further seeds at run time."""
import base64, json, os, struct, zlib

here = os.path.dirname(os.path.abspath(__file__))


def out(target, name, data):
    path = os.path.join(here, 'corpus', target, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'wb') as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def png(width, height, colour_type, bit_depth, rows, palette=None):
    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))
    head = struct.pack('>IIBBBBB', width, height, bit_depth, colour_type, 0, 0, 0)
    raw = b''.join(b'\0' + r for r in rows)
    extra = chunk(b'PLTE', palette) if palette else b''
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', head) + extra +
            chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))


rgba = png(4, 4, 6, 8, [b''.join(bytes([x * 60, y * 60, 128, 255 - 20 * x]) for x in range(4))
                        for y in range(4)])
out('texture', 'rgba8-4x4.png', rgba)
out('texture', 'grey16-3x2.png', png(3, 2, 0, 16, [struct.pack('>3H', 0, 30000, 65535)] * 2))
out('texture', 'palette-2x2.png', png(2, 2, 3, 8, [b'\0\1', b'\1\0'], palette=b'\xff\0\0\0\0\xff'))
out('texture', 'grey-alpha-1x1.png', png(1, 1, 4, 8, [b'\x80\x40']))

cube = ''.join('v %d %d %d\n' % (x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1))
cube += 'vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n'
cube += 'mtllib input.mtl\nusemtl red\ng side\ns 1\n'
cube += 'f 1/1/1 2/2/1 4/3/1 3/4/1\nf 5/1 7/2 8/3 6/4\nf 1 5 6 2\nf 3 4 8 7\no top\nf 2 6 8 4\nf -8 -6 -2 -4\n'
out('obj', 'cube-quads.obj', cube)
out('obj', 'triangle-negative-indices.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nl 1 2\np 3\n')
out('obj', 'textured-material.obj',
    'mtllib input.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n'
    'usemtl m\nf 1/1 2/2 3/3 4/4\n')


def gltf_doc(binary_buffer):
    positions = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0)
    normals = struct.pack('<9f', 0, 0, 1, 0, 0, 1, 0, 0, 1)
    uvs = struct.pack('<6f', 0, 0, 1, 0, 0, 1)
    indices = struct.pack('<3H', 0, 1, 2) + b'\0\0'
    blob = positions + normals + uvs + indices
    doc = {
        'asset': {'version': '2.0'},
        'buffers': [{'byteLength': len(blob)}],
        'bufferViews': [{'buffer': 0, 'byteOffset': 0, 'byteLength': 36},
                        {'buffer': 0, 'byteOffset': 36, 'byteLength': 36},
                        {'buffer': 0, 'byteOffset': 72, 'byteLength': 24},
                        {'buffer': 0, 'byteOffset': 96, 'byteLength': 6}],
        'accessors': [{'bufferView': 0, 'componentType': 5126, 'count': 3, 'type': 'VEC3',
                       'min': [0, 0, 0], 'max': [1, 1, 0]},
                      {'bufferView': 1, 'componentType': 5126, 'count': 3, 'type': 'VEC3'},
                      {'bufferView': 2, 'componentType': 5126, 'count': 3, 'type': 'VEC2'},
                      {'bufferView': 3, 'componentType': 5123, 'count': 3, 'type': 'SCALAR'}],
        'images': [{'uri': 'data:image/png;base64,' + base64.b64encode(rgba).decode()}],
        'textures': [{'source': 0}],
        'materials': [{'pbrMetallicRoughness': {'baseColorFactor': [1, 0.5, 0.2, 1],
                                                'baseColorTexture': {'index': 0}}}],
        'meshes': [{'primitives': [{'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2},
                                    'indices': 3, 'material': 0}]}],
        'nodes': [{'mesh': 0, 'translation': [0, 1, 0]}, {'children': [0], 'scale': [2, 2, 2]}],
        'scenes': [{'nodes': [1]}],
        'scene': 0,
    }
    if not binary_buffer:
        doc['buffers'][0]['uri'] = 'data:application/octet-stream;base64,' + \
            base64.b64encode(blob).decode()
    return doc, blob


doc, _ = gltf_doc(False)
out('gltf', 'triangle-embedded.gltf', json.dumps(doc, indent=1))
doc, blob = gltf_doc(True)
text = json.dumps(doc).encode()
text += b' ' * (-len(text) % 4)
glb = (struct.pack('<I', len(text)) + b'JSON' + text + struct.pack('<I', len(blob)) + b'BIN\0' + blob)
out('gltf', 'triangle.glb', b'glTF' + struct.pack('<II', 2, 12 + len(glb)) + glb)


# A manifest as facet writes it (two frames of colour and depth), and the
# same run as a journal: its settings on one line, then a line per image.
def manifest_entry(frame, kind, fmt):
    return {'frame': frame, 'camera': 'main', 'pass': kind, 'format': fmt, 'style': 'inline',
            'path': '%s.%04d.%s' % (kind, frame, fmt), 'sha256': '%064x' % (frame * 7919 + len(kind))}


settings = {
    'manifest_version': 2,
    'facet': {'version': '0.1.0', 'commit': '26f42cf028c6', 'build': 'Release, avx2, gcc 12.2.0'},
    'scene': '../../fuzz_overridden.yaml', 'scene_sha256': '%064x' % 12345, 'style': 'inline',
    'size': [64, 48], 'fps': 24.0, 'display': {'exposure': 0.0, 'tonemap': 'none'},
    'output_template': '{scene}/{pass}.{frame}.{ext}',
    'overrides': [{'key': 'output.passes', 'value': '[color,depth]',
                   'origin': 'command line --passes color,depth'}],
}
frames = [{'frame': f, 'camera': 'main'} for f in (1, 2)]
files = [manifest_entry(f, k, x) for f in (1, 2) for k in ('color', 'depth') for x in ('png', 'exr')]
out('manifest', 'two-frames.json', json.dumps(dict(settings, frames=frames, files=files), indent=2))
journal = json.dumps(dict(settings, frames=[], files=[])) + '\n'
for f in frames:
    journal += json.dumps(dict(settings, frames=[f], files=[e for e in files if e['frame'] == f['frame']])) + '\n'
out('manifest', 'journal.json', journal)

# -D values, one per line, for the scene the override harness writes.
out('override', 'camera-and-size', 'camera.fov=30\noutput.size=[32, 24]\n')
out('override', 'material-mapping',
    'objects.0.material={color: [1, 0, 0], shininess: 5}\nlights.0.intensity=0.5\n'
    'style.occlusion.radius=0.2\n')
out('override', 'colour-and-keys',
    'objects.0.material.color=#ff8800\ncamera.fov={keys: {1: 20, 4: 60}}\noutput.frames=2-3\n')
out('override', 'replaced-list-item',
    'lights.0={type: point, position: [1, 2, 3], intensity: 4}\nobjects.0.translate=[0, 1, 0]\n')


# Environment maps: Radiance .hdr, flat and run-length encoded scanlines,
# and a small scanline OpenEXR file (half RGB, no compression).
def rgbe(value):
    import math
    if value <= 0:
        return bytes(4)
    mantissa, exponent = math.frexp(value)
    m = int(mantissa * 256)
    return bytes([m, m, m, exponent + 128])


flat = b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n' + b''.join(
    rgbe(0.5 * (i + 1)) for i in range(8))
out('environment', 'flat-4x2.hdr', flat)
row = b'\x02\x02\x00\x10' + b''.join(bytes([0x80 + 16, v]) for v in (128, 128, 128, 129))
out('environment', 'rle-16x8.hdr', b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n' + row * 8)


def exr(width, height):
    def attribute(name, kind, value):
        return name.encode() + b'\0' + kind.encode() + b'\0' + struct.pack('<i', len(value)) + value
    channels = b''.join(c + b'\0' + struct.pack('<iB3xii', 1, 0, 1, 1) for c in (b'B', b'G', b'R'))
    box = struct.pack('<4i', 0, 0, width - 1, height - 1)
    header = (b'v/1\x01' + struct.pack('<I', 2) +
              attribute('channels', 'chlist', channels + b'\0') +
              attribute('compression', 'compression', b'\0') +
              attribute('dataWindow', 'box2i', box) + attribute('displayWindow', 'box2i', box) +
              attribute('lineOrder', 'lineOrder', b'\0') +
              attribute('pixelAspectRatio', 'float', struct.pack('<f', 1)) +
              attribute('screenWindowCenter', 'v2f', struct.pack('<2f', 0, 0)) +
              attribute('screenWindowWidth', 'float', struct.pack('<f', 1)) + b'\0')
    lines = []
    for y in range(height):
        pixels = b''.join(struct.pack('<%de' % width, *[0.25 * (x + y + c) for x in range(width)])
                          for c in range(3))
        lines.append(struct.pack('<ii', y, len(pixels)) + pixels)
    offsets, at = [], len(header) + 8 * height
    for line in lines:
        offsets.append(at)
        at += len(line)
    return header + struct.pack('<%dQ' % height, *offsets) + b''.join(lines)


out('environment', 'half-rgb-4x2.exr', exr(4, 2))


# PLY: a square as ASCII and as binary; the assimp harness: a byte that
# names the file (0 .stl, 1 .fbx, 2 .dae, 3 .3ds), then the file.
ply_head = ('ply\nformat %s 1.0\nelement vertex 4\nproperty float x\nproperty float y\n'
            'property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n')
corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
out('ply', 'square-ascii.ply', ply_head % 'ascii' + ''.join('%d %d %d\n' % c for c in corners) +
    '4 0 1 2 3\n')
out('ply', 'square-binary.ply', (ply_head % 'binary_little_endian').encode() +
    b''.join(struct.pack('<3f', *c) for c in corners) + struct.pack('<B4i', 4, 0, 1, 2, 3))
triangle = struct.pack('<12fH', 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0)
out('assimp', 'stl-binary-triangle', b'\0' + b'facet fuzz seed'.ljust(80, b' ') +
    struct.pack('<I', 1) + triangle)
out('assimp', 'stl-ascii-triangle', b'\0solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n'
    b'vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n')
