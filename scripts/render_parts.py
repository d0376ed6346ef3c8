#!/usr/bin/env python3
"""Render a papercraft parts.ply (faces coloured by part) to a PNG, with nothing but the
Python standard library: orthographic view, painter's algorithm, Lambert shading.

  scripts/render_parts.py out/camel/parts.ply camel-parts.png
  scripts/render_parts.py parts.ply parts.png --azimuth 30 --elevation 20 --size 900 --views 2

--views 2 draws the model from the front and from behind, side by side.
"""
import argparse
import math
import struct
import sys
import zlib


def read_ply(path):
    with open(path) as f:
        lines = f.read().split("\n")
    end = lines.index("end_header")
    header = lines[:end]
    n_vertices = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    n_faces = int(next(l for l in header if l.startswith("element face")).split()[2])
    face_props = []
    in_face = False
    for l in header:
        if l.startswith("element"):
            in_face = l.startswith("element face")
        elif l.startswith("property") and in_face and "list" not in l:
            face_props.append(l.split()[-1])
    vertices = [tuple(map(float, lines[end + 1 + i].split()[:3])) for i in range(n_vertices)]
    faces, colours = [], []
    for i in range(n_faces):
        t = lines[end + 1 + n_vertices + i].split()
        n = int(t[0])
        ids = list(map(int, t[1:1 + n]))
        props = dict(zip(face_props, t[1 + n:]))
        colour = tuple(int(props.get(c, 200)) for c in ("red", "green", "blue"))
        for k in range(1, n - 1):
            faces.append((ids[0], ids[k], ids[k + 1]))
            colours.append(colour)
    return vertices, faces, colours


def write_png(path, width, height, pixels):
    raw = b"".join(b"\x00" + bytes(pixels[y * width * 3:(y + 1) * width * 3]) for y in range(height))

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def render(vertices, faces, colours, pixels, width, height, x0, size, azimuth, elevation):
    a, e = math.radians(azimuth), math.radians(elevation)
    # camera basis: right, up, towards the viewer (y up)
    forward = (math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a))
    right = (math.cos(a), 0.0, -math.sin(a))
    up = (forward[1] * right[2] - forward[2] * right[1], forward[2] * right[0] - forward[0] * right[2],
          forward[0] * right[1] - forward[1] * right[0])
    dot = lambda p, q: p[0] * q[0] + p[1] * q[1] + p[2] * q[2]
    lo = [min(v[i] for v in vertices) for i in range(3)]
    hi = [max(v[i] for v in vertices) for i in range(3)]
    centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
    rel = [tuple(v[i] - centre[i] for i in range(3)) for v in vertices]
    xs = [dot(v, right) for v in rel]
    ys = [dot(v, up) for v in rel]
    zs = [dot(v, forward) for v in rel]
    extent = max(max(map(abs, xs)), max(map(abs, ys))) or 1.0
    scale = 0.45 * size / extent
    sx = [x0 + size / 2 + x * scale for x in xs]
    sy = [height / 2 - y * scale for y in ys]
    light = (0.3, 0.5, 0.81)
    order = sorted(range(len(faces)), key=lambda k: sum(zs[i] for i in faces[k]))
    for k in order:
        i, j, l = faces[k]
        p, q, r = rel[i], rel[j], rel[l]
        u = (q[0] - p[0], q[1] - p[1], q[2] - p[2])
        v = (r[0] - p[0], r[1] - p[1], r[2] - p[2])
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        length = math.sqrt(dot(n, n)) or 1.0
        n_view = (dot(n, right) / length, dot(n, up) / length, dot(n, forward) / length)
        shade = 0.35 + 0.65 * abs(dot(n_view, light))
        rgb = bytes(min(255, int(c * shade)) for c in colours[k])
        ax, ay, bx, by, cx, cy = sx[i], sy[i], sx[j], sy[j], sx[l], sy[l]
        area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if area == 0:
            continue
        xmin, xmax = max(int(min(ax, bx, cx)), x0), min(int(max(ax, bx, cx)) + 1, x0 + size - 1)
        ymin, ymax = max(int(min(ay, by, cy)), 0), min(int(max(ay, by, cy)) + 1, height - 1)
        for y in range(ymin, ymax + 1):
            py = y + 0.5
            row = y * width
            for x in range(xmin, xmax + 1):
                px = x + 0.5
                w0 = (bx - px) * (cy - py) - (by - py) * (cx - px)
                w1 = (cx - px) * (ay - py) - (cy - py) * (ax - px)
                w2 = (ax - px) * (by - py) - (ay - py) * (bx - px)
                if (w0 >= 0 and w1 >= 0 and w2 >= 0) or (w0 <= 0 and w1 <= 0 and w2 <= 0):
                    o = 3 * (row + x)
                    pixels[o:o + 3] = rgb


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("ply")
    parser.add_argument("png")
    parser.add_argument("--azimuth", type=float, default=35.0, help="degrees about the y axis")
    parser.add_argument("--elevation", type=float, default=20.0, help="degrees above the x-z plane")
    parser.add_argument("--size", type=int, default=700, help="pixels per view (square)")
    parser.add_argument("--views", type=int, default=2, choices=(1, 2), help="2: also from behind")
    args = parser.parse_args()
    vertices, faces, colours = read_ply(args.ply)
    if not faces:
        sys.exit("no faces in " + args.ply)
    width, height = args.size * args.views, args.size
    pixels = bytearray(b"\xff" * (width * height * 3))
    for view in range(args.views):
        render(vertices, faces, colours, pixels, width, height, view * args.size, args.size,
               args.azimuth + 180.0 * view, args.elevation)
    write_png(args.png, width, height, pixels)


if __name__ == "__main__":
    main()
