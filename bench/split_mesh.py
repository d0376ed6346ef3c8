#!/usr/bin/env python3
"""Splits every triangle of an OFF mesh into four at its edge midpoints (shared between the
two triangles of an edge, so the result stays a manifold mesh of the same surface).

    bench/split_mesh.py IN.off OUT.off [--times N]

Used by bench/scaling.sh to make dense copies of a mesh (75k faces -> 302k -> 1.2M).
Python standard library only; coordinates written with 17 significant digits."""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from textured_model import read_off  # noqa: E402  (polygons fan-triangulated)


def split(vertices, faces):
    vertices = list(vertices)
    middle = {}

    def midpoint(a, b):
        key = (a, b) if a < b else (b, a)
        index = middle.get(key)
        if index is None:
            pa, pb = vertices[a], vertices[b]
            index = len(vertices)
            vertices.append(tuple(0.5 * (x + y) for x, y in zip(pa, pb)))
            middle[key] = index
        return index

    out = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return vertices, out


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        f.write("".join(f"{x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in vertices))
        f.write("".join(f"3 {a} {b} {c}\n" for a, b, c in faces))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--times", type=int, default=1)
    args = parser.parse_args()
    vertices, faces = read_off(args.input)
    for _ in range(args.times):
        vertices, faces = split(vertices, faces)
    write_off(args.output, vertices, faces)


if __name__ == "__main__":
    main()
