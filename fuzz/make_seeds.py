#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets into fuzz/corpus/<target>/ (Python standard
library only): generated shapes in every mesh format (ascii, and binary for PLY and STL),
the small files of the loader tests, the shipped configs and job files.

usage: fuzz/make_seeds.py PAPERCRAFT_BINARY [CGAL_MESH_FOLDER]

Run it once to (re)seed; fuzz/run.sh then grows the corpora and merges them back small."""
import os
import shutil
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from textured_model import read_off  # noqa: E402  (vertices, fan-triangulated faces)
CORPUS = os.path.join(ROOT, "fuzz", "corpus")

TETRA_POINTS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_FACES = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]


def put(target, name, data):
    folder = os.path.join(CORPUS, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as out:
        out.write(data if isinstance(data, bytes) else data.encode())


def ply_binary(vertices, faces, big_endian, extra_header=""):
    e = ">" if big_endian else "<"
    kind = "binary_big_endian" if big_endian else "binary_little_endian"
    header = (f"ply\nformat {kind} 1.0\n{extra_header}element vertex {len(vertices)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    body = b"".join(struct.pack(e + "3f", *v) for v in vertices)
    body += b"".join(struct.pack(e + "B", len(f)) + struct.pack(e + f"{len(f)}i", *f)
                     for f in faces)
    return header.encode() + body


def ply_ascii(vertices, faces, extra_vertex_props=()):
    lines = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}",
             "property float x", "property float y", "property float z"]
    lines += [f"property {t} {n}" for t, n, _ in extra_vertex_props]
    lines += [f"element face {len(faces)}", "property list uchar int vertex_indices",
              "end_header"]
    for v in vertices:
        lines.append(" ".join(str(c) for c in v) +
                     "".join(f" {value}" for _, _, value in extra_vertex_props))
    lines += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return "\n".join(lines) + "\n"


def triangles(faces):
    for f in faces:
        for i in range(1, len(f) - 1):
            yield (f[0], f[i], f[i + 1])


def stl_binary(vertices, faces, header=b"binary"):
    tris = list(triangles(faces))
    data = header.ljust(80, b" ") + struct.pack("<I", len(tris))
    for t in tris:
        data += struct.pack("<3f", 0, 0, 0)
        for i in t:
            data += struct.pack("<3f", *vertices[i])
        data += b"\0\0"
    return data


def stl_ascii(vertices, faces):
    out = ["solid shape"]
    for t in triangles(faces):
        out += ["  facet normal 0 0 0", "    outer loop"]
        out += [f"      vertex {vertices[i][0]} {vertices[i][1]} {vertices[i][2]}" for i in t]
        out += ["    endloop", "  endfacet"]
    return "\n".join(out + ["endsolid shape"]) + "\n"


def obj(vertices, faces, uvs=False):
    out = [f"v {x} {y} {z}" for x, y, z in vertices]
    if uvs:
        out += [f"vt {x % 1} {y % 1}" for x, y, _ in vertices]
        out += ["usemtl skin"] + ["f " + " ".join(f"{i + 1}/{i + 1}" for i in f) for f in faces]
    else:
        out += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(out) + "\n"


def off(vertices, faces, colours=False):
    out = ["COFF" if colours else "OFF", f"{len(vertices)} {len(faces)} 0"]
    out += [f"{x} {y} {z}" + (" 200 100 50 255" if colours else "") for x, y, z in vertices]
    out += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return "\n".join(out) + "\n"


def mesh_seeds(binary):
    shapes = {
        "tetra": None,
        "box": ["divisions_x=1", "divisions_y=1", "divisions_z=1"],
        "sphere": ["subdivisions=0"],
        "open_cylinder": ["segments=5", "rings=1"],
        "torus": ["segments=5", "tube_segments=3"],
        "pawn": ["segments=4", "profile_samples=7"],
        "cylinder_two_holes": ["segments=8", "rings=4", "hole_rings=1", "hole_segments=2"],
    }
    with tempfile.TemporaryDirectory() as tmp:
        for name, params in shapes.items():
            if params is None:
                vertices, faces = TETRA_POINTS, TETRA_FACES
            else:
                path = os.path.join(tmp, name + ".off")
                args = [binary, "generate", name, path]
                for p in params:
                    args += ["--param", p]
                subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
                vertices, faces = read_off(path)
            put("load_obj", name + ".obj", obj(vertices, faces))
            put("load_off", name + ".off", off(vertices, faces))
            put("load_ply", name + ".ply", ply_ascii(vertices, faces))
            put("load_ply", name + "-le.ply", ply_binary(vertices, faces, False))
            put("load_stl", name + ".stl", stl_ascii(vertices, faces))
            put("load_stl", name + "-binary.stl", stl_binary(vertices, faces))
    v, f = TETRA_POINTS, TETRA_FACES
    quad = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    put("load_obj", "tetra-uv.obj", "mtllib skin.mtl\n" + obj(v, f, uvs=True))
    put("load_obj", "quad.obj", obj(quad, [(0, 1, 2, 3)]))
    put("load_obj", "normals.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n")
    put("load_off", "tetra-colours.off", off(v, f, colours=True))
    put("load_off", "quad.off", off(quad, [(0, 1, 2, 3)]))
    put("load_ply", "tetra-be.ply", ply_binary(v, f, True))
    put("load_ply", "tetra-colours.ply",
        ply_ascii(v, f, [("uchar", "red", 200), ("uchar", "green", 10), ("uchar", "blue", 99)]))
    put("load_ply", "tetra-texture.ply",
        ply_binary(v, f, False, "comment TextureFile skin.png\n"))
    put("load_stl", "tetra-solid-header.stl", stl_binary(v, f, b"solid but binary"))


def gltf_document(vertices, faces, uri=None, extra=None):
    """A glTF document of one indexed triangle primitive; its buffer a data URI unless `uri`.
    Returns (json text, buffer bytes)."""
    import base64
    import json
    positions = b"".join(struct.pack("<3f", *p) for p in vertices)
    indices = b"".join(struct.pack("<3H", *t) for t in faces)
    indices += b"\0" * (-len(indices) % 4)
    buffer = positions + indices
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "scale": [2, 2, 2], "children": [1]},
                  {"mesh": 0, "translation": [3, 0, 0], "rotation": [0, 0, 0.7071068, 0.7071068]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(vertices), "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5123, "count": 3 * len(faces), "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": 6 * len(faces)}],
        "buffers": [{"byteLength": len(buffer)}],
    }
    if uri is None:
        doc["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                    base64.b64encode(buffer).decode())
    elif uri:
        doc["buffers"][0]["uri"] = uri
    if extra:
        doc.update(extra)
    return json.dumps(doc), buffer


def glb(text, buffer):
    body = text.encode() + b" " * (-len(text.encode()) % 4)
    chunks = struct.pack("<I4s", len(body), b"JSON") + body
    chunks += struct.pack("<I4s", len(buffer), b"BIN\0") + buffer
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def three_mf(vertices, faces, colour=True):
    """A 3MF package of one mesh object, built twice as components (the second moved)."""
    import io
    import zipfile
    vs = "".join('<vertex x="%g" y="%g" z="%g"/>' % p for p in vertices)
    ts = "".join('<triangle v1="%d" v2="%d" v3="%d"%s/>' % (t + (' pid="2" p1="0"' if colour else "",))
                 for t in faces)
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n<model unit="millimeter" xml:lang="en-US" '
             'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>'
             '<basematerials id="2"><base name="red" displaycolor="#FF0000"/></basematerials>'
             '<object id="1" type="model"%s><mesh><vertices>%s</vertices><triangles>%s</triangles>'
             '</mesh></object><object id="3" type="model"><components><component objectid="1"/>'
             '<component objectid="1" transform="1 0 0 0 1 0 0 0 1 5 0 0"/></components></object>'
             '</resources><build><item objectid="3"/></build></model>') % (
                 ' pid="2" pindex="0"' if colour else "", vs, ts)
    rels = ('<?xml version="1.0" encoding="UTF-8"?>\n<Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model"'
            ' Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>'
            '</Relationships>')
    types = ('<?xml version="1.0" encoding="UTF-8"?>\n<Types xmlns="http://schemas.openxmlformats.'
             'org/package/2006/content-types"><Default Extension="rels" ContentType="application/'
             'vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType='
             '"application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>')
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("[Content_Types].xml", types)
        z.writestr("_rels/.rels", rels)
        z.writestr("3D/3dmodel.model", model)
    return out.getvalue()


def scene_seeds():
    v, f = TETRA_POINTS, TETRA_FACES
    put("load_3mf", "tetra-components.3mf", three_mf(v, f))
    put("load_3mf", "tetra-plain.3mf", three_mf(v, f, colour=False))
    text, _ = gltf_document(v, f)
    put("load_gltf", "tetra.gltf", text)
    strip_text, _ = gltf_document(v, f, extra=None)
    put("load_gltf", "tetra-strip.gltf", strip_text.replace('"mode": 4', '"mode": 5'))
    put("load_gltf", "tetra-fan.gltf", strip_text.replace('"mode": 4', '"mode": 6'))
    text, buffer = gltf_document(v, f, uri="")
    put("load_glb", "tetra.glb", glb(text, buffer))
    put("load_glb", "tetra-lines.glb", glb(text.replace('"mode": 4', '"mode": 1'), buffer))


def other_seeds(cgal):
    put("mtl", "two.mtl", "newmtl a\nKd 1 1 1\nmap_Kd -s 1 1 1 wood.png\n"
        "newmtl b\nmap_Kd -o 0.5 0.5 0 -clamp on stone texture.jpg\n")
    put("mtl", "empty-name.mtl", "newmtl\nmap_Kd\n# comment\nnewmtl c\r\nmap_Kd  c.png \r\n")
    for name in sorted(os.listdir(os.path.join(ROOT, "configs"))):
        put("config", name, open(os.path.join(ROOT, "configs", name), "rb").read())
    put("batch_job", "job.yaml", "inputs: [job.yaml, '*.yaml']\noutput: out\ntolerance: 2%\n"
        "threads: 2\nheight_mm: 150\nmin_width_mm: 5\nmin_area_mm2: 100\nshard: 1/4\n")
    put("batch_job", "flow.yaml", "{inputs: [job.yaml], output: o, config: c.yaml, "
        "tolerance: 0.004}\n")
    if cgal:
        for name in sorted(os.listdir(cgal)):
            path = os.path.join(cgal, name)
            if name.endswith(".off") and os.path.getsize(path) <= 2048:
                shutil.copy(path, os.path.join(CORPUS, "load_off", "cgal-" + name))


def array_seeds():
    """load_arrays: a vertex count byte, 3 doubles per vertex, then 3 int32 per triangle."""
    import math

    def arrays(points, faces):
        data = bytes([len(points)])
        for p in points:
            data += struct.pack("<3d", *p)
        for f in faces:
            data += struct.pack("<3i", *f)
        return data
    put("load_arrays", "tetrahedron", arrays(TETRA_POINTS, TETRA_FACES))
    put("load_arrays", "nan-vertex", arrays(TETRA_POINTS[:3] + [(0, 0, math.nan)], TETRA_FACES))
    put("load_arrays", "index-out-of-range", arrays(TETRA_POINTS, TETRA_FACES[:3] + [(0, 3, 9)]))
    put("load_arrays", "negative-index", arrays(TETRA_POINTS, TETRA_FACES[:3] + [(0, -1, 2)]))
    put("load_arrays", "duplicate-face", arrays(TETRA_POINTS, TETRA_FACES + TETRA_FACES[:1]))
    put("load_arrays", "no-faces", arrays(TETRA_POINTS, []))
    points = TETRA_POINTS + [(1, 1, 0), (1, 1, 1)]  # a third face on edge 1-2
    put("load_arrays", "non-manifold-edge",
        arrays(points, TETRA_FACES + [(1, 2, 4), (1, 4, 5), (2, 5, 4)]))


if __name__ == "__main__" and sys.argv[1:2] == ["--arrays"]:
    array_seeds()  # the load_arrays seeds alone
    sys.exit(0)
if __name__ == "__main__" and sys.argv[1:2] == ["--scenes"]:
    scene_seeds()  # the glTF, GLB and 3MF seeds alone
    sys.exit(0)
if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    mesh_seeds(sys.argv[1])
    scene_seeds()
    array_seeds()
    other_seeds(sys.argv[2] if len(sys.argv) > 2 else None)
