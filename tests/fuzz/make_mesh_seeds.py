#!/usr/bin/env python3
"""Writes the mesh fuzzer's seeds of the formats beside OBJ into seeds/mesh/: a regular
tetrahedron (corners (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1), faces outward) as ASCII and
binary PLY, ASCII and binary STL, a .glb and a .gltf with its buffer in a data: URI.

    python3 tests/fuzz/make_mesh_seeds.py
"""
import base64
import json
import os
import struct

V = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
F = [(1, 3, 2), (0, 2, 3), (0, 3, 1), (0, 1, 2)]  # each leaves out one corner, outward


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normal(f):
    n = cross(sub(V[f[1]], V[f[0]]), sub(V[f[2]], V[f[0]]))
    length = sum(c * c for c in n) ** 0.5
    return tuple(c / length for c in n)


for f in F:  # outward: away from the corner left out
    out = ({0, 1, 2, 3} - set(f)).pop()
    assert sum(a * b for a, b in zip(normal(f), V[out])) < 0

here = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'seeds', 'mesh')
os.makedirs(here, exist_ok=True)


def write(name, data):
    with open(os.path.join(here, name), 'wb') as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def ply_header(fmt):
    return ('ply\nformat %s 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n'
            'element face 4\nproperty list uchar int vertex_indices\nend_header\n' % fmt)


write('tetra_ascii.ply', ply_header('ascii') + ''.join('%d %d %d\n' % v for v in V) + ''.join('3 %d %d %d\n' % f for f in F))
write('tetra_binary.ply', ply_header('binary_little_endian').encode() + b''.join(struct.pack('<3f', *v) for v in V)
      + b''.join(struct.pack('<B3i', 3, *f) for f in F))
stl = 'solid tetra\n'
for f in F:
    stl += 'facet normal %.6f %.6f %.6f\n outer loop\n' % normal(f)
    stl += ''.join('  vertex %d %d %d\n' % V[i] for i in f)
    stl += ' endloop\nendfacet\n'
write('tetra_ascii.stl', stl + 'endsolid tetra\n')
write('tetra_binary.stl', b'binary STL: a regular tetrahedron'.ljust(80, b'\0') + struct.pack('<I', 4)
      + b''.join(struct.pack('<3f', *normal(f)) + b''.join(struct.pack('<3f', *V[i]) for i in f) + b'\0\0' for f in F))

buffer = b''.join(struct.pack('<3f', *v) for v in V) + b''.join(struct.pack('<3H', *f) for f in F)


def gltf(buffer_entry):
    return {'asset': {'version': '2.0'}, 'scene': 0, 'scenes': [{'nodes': [0]}], 'nodes': [{'mesh': 0}],
            'meshes': [{'primitives': [{'attributes': {'POSITION': 0}, 'indices': 1}]}],
            'accessors': [{'bufferView': 0, 'componentType': 5126, 'count': 4, 'type': 'VEC3',
                           'min': [-1, -1, -1], 'max': [1, 1, 1]},
                          {'bufferView': 1, 'componentType': 5123, 'count': 12, 'type': 'SCALAR'}],
            'bufferViews': [{'buffer': 0, 'byteOffset': 0, 'byteLength': 48},
                            {'buffer': 0, 'byteOffset': 48, 'byteLength': 24}],
            'buffers': [buffer_entry]}


write('tetra.gltf', json.dumps(gltf({'byteLength': len(buffer), 'uri': 'data:application/octet-stream;base64,'
                                     + base64.b64encode(buffer).decode()}), separators=(',', ':')))
js = json.dumps(gltf({'byteLength': len(buffer)}), separators=(',', ':')).encode()
js += b' ' * (-len(js) % 4)
write('tetra.glb', b'glTF' + struct.pack('<II', 2, 12 + 8 + len(js) + 8 + len(buffer))
      + struct.pack('<I', len(js)) + b'JSON' + js + struct.pack('<I', len(buffer)) + b'BIN\0' + buffer)
