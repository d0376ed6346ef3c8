#!/usr/bin/env python3
"""Makes a textured OBJ from an OFF mesh, for bench/texture_bake.sh.

    textured_model.py MESH.off OUT_DIR [SIZE]

writes OUT_DIR/<name>.obj with a UV per face corner (a longitude-latitude projection about
the mesh's centre, so the texture wraps once around it with a UV seam where longitude jumps
from 1 back to 0), OUT_DIR/<name>.mtl and OUT_DIR/<name>.png (SIZE x SIZE pixels, 2048 by
default: hue by longitude, bands by latitude, a dark grid every 1/16), so a wrong sample
shows as a broken grid line or a colour jump on the printed pieces.
"""
import colorsys
import math
import os
import struct
import sys
import zlib


def read_off(path):
    words = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0]
            words.extend(line.split())
    if words[0].endswith('OFF'):
        words = words[1:]
    nv, nf = int(words[0]), int(words[1])
    at = 3
    vertices = []
    for _ in range(nv):
        vertices.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        idx = [int(w) for w in words[at + 1:at + 1 + n]]
        at += 1 + n
        for k in range(1, n - 1):  # fan
            faces.append((idx[0], idx[k], idx[k + 1]))
    return vertices, faces


def texture(size):
    rows = []
    for y in range(size):
        v = 1.0 - (y + 0.5) / size
        band = 0.55 + 0.35 * (int(v * 8) % 2)
        row = bytearray([0])  # filter: none
        for x in range(size):
            u = (x + 0.5) / size
            r, g, b = colorsys.hsv_to_rgb(u, 0.75, band)
            if min(abs(u * 16 - round(u * 16)), abs(v * 16 - round(v * 16))) < 0.04:
                r, g, b = 0.1, 0.1, 0.1
            row += bytes((int(r * 255), int(g * 255), int(b * 255)))
        rows.append(bytes(row))
    raw = zlib.compress(b''.join(rows), 6)

    def chunk(kind, data):
        body = kind + data
        return struct.pack('>I', len(data)) + body + struct.pack('>I', zlib.crc32(body))

    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', size, size, 8, 2, 0, 0, 0))
            + chunk(b'IDAT', raw) + chunk(b'IEND', b''))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    mesh, out = sys.argv[1], sys.argv[2]
    size = int(sys.argv[3]) if len(sys.argv) > 3 else 2048
    name = os.path.splitext(os.path.basename(mesh))[0]
    vertices, faces = read_off(mesh)
    centre = [sum(p[i] for p in vertices) / len(vertices) for i in range(3)]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name + '.png'), 'wb') as f:
        f.write(texture(size))
    with open(os.path.join(out, name + '.mtl'), 'w') as f:
        f.write('newmtl skin\nKd 1 1 1\nmap_Kd %s.png\n' % name)
    with open(os.path.join(out, name + '.obj'), 'w') as f:
        f.write('mtllib %s.mtl\n' % name)
        for p in vertices:
            f.write('v %.9g %.9g %.9g\n' % p)
        f.write('usemtl skin\n')
        corner = 0
        for face in faces:
            uvs = []
            for i in face:
                d = [vertices[i][k] - centre[k] for k in range(3)]
                r = math.sqrt(sum(c * c for c in d)) or 1.0
                u = (math.atan2(d[1], d[0]) / (2 * math.pi)) % 1.0
                v = 0.5 + math.asin(max(-1.0, min(1.0, d[2] / r))) / math.pi
                uvs.append([u, v])
            # A triangle across the longitude seam keeps its corners together (u beyond 1).
            if max(uv[0] for uv in uvs) - min(uv[0] for uv in uvs) > 0.5:
                for uv in uvs:
                    if uv[0] < 0.5:
                        uv[0] += 1.0
            for uv in uvs:
                f.write('vt %.6f %.6f\n' % tuple(uv))
            f.write('f %d/%d %d/%d %d/%d\n' % (face[0] + 1, corner + 1, face[1] + 1, corner + 2,
                                               face[2] + 1, corner + 3))
            corner += 3


if __name__ == '__main__':
    main()
