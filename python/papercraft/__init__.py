"""papercraft: paper patterns from triangle meshes, certified to a tolerance.

    import papercraft
    V, F = papercraft.load("bunny.obj")            # float64 (n, 3), int32 (m, 3)
    result = papercraft.run(V, F, tolerance="2%", height_mm=150)
    print(result.certified, result.hausdorff_bound_percent, len(result.strips))
    result.write("out")                            # out/model/pattern.pdf, ..., out/run.json

Bad input (a malformed file, NaN, a wrong shape, an index out of range, a bad config) raises
ValueError with the loader's or the config's message; a file that cannot be read raises
OSError. The GIL is released while a mesh loads and while the pipeline runs.
"""

import json as _json
import os as _os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional

import numpy as _np

from . import _papercraft

__version__ = _papercraft.__version__
__all__ = ["load", "run", "Result", "Strip"]


def load(path) -> tuple:
    """Reads a mesh file (OBJ, OFF, PLY, STL, glTF/GLB, 3MF) through papercraft's loader, with
    its repairs: returns (V, F), float64 (n, 3) positions and int32 (m, 3) triangles."""
    return _papercraft.load(str(path))


@dataclass
class Strip:
    """One flat strip of strips.json: its 3D and flat vertices, triangles, UVs where the input
    had them, and its boundary edges (cut, seam or open, with the seam's neighbour and label)."""

    id: int
    source_strip: int
    vertices3d: _np.ndarray
    vertices2d: _np.ndarray
    triangles: _np.ndarray
    uv: Optional[_np.ndarray]
    boundary: List[Dict[str, Any]]

    @property
    def seams(self) -> List[Dict[str, Any]]:
        """The boundary edges glued to another strip (or to this one)."""
        return [edge for edge in self.boundary if edge.get("kind") == "seam"]


@dataclass
class Result:
    """What one run made. Nothing is on disk until write()."""

    name: str
    report: Dict[str, Any]
    strips: List[Strip]
    pieces: List[Dict[str, Any]]
    _output: Any = field(repr=False)

    @property
    def certified(self) -> bool:
        return bool(self.report["result"]["certified"])

    @property
    def hausdorff_bound(self) -> float:
        return float(self.report["result"]["hausdorff_bound"])

    @property
    def hausdorff_bound_percent(self) -> float:
        return float(self.report["result"]["hausdorff_bound_percent"])

    @property
    def pages(self) -> int:
        return int(self.report["result"]["pages"])

    @property
    def effort(self) -> Dict[str, Any]:
        """The assembly effort (report.json "effort"): "total", each term ("things_to_cut",
        "seam_chains", "sawtooth_corners", ...), "cost" per term and the "weights"."""
        return dict(self.report["effort"])

    @property
    def notes(self) -> List[str]:
        return list(self.report.get("notes", []))

    @property
    def files(self) -> Dict[str, bytes]:
        """Every file of the model's folder, by name, as `papercraft run` writes them."""
        return dict(self._output.files)

    def write(self, folder) -> str:
        """Writes the model's files into folder/<name>/ and the run's summary (run.json,
        run.jsonl) into folder, as `papercraft run --out folder` does; returns the model's
        folder."""
        self._output.write(str(folder))
        return _os.path.join(str(folder), self.name)


def _strip(s: Dict[str, Any]) -> Strip:
    uv = s.get("uv")
    return Strip(
        id=int(s["id"]),
        source_strip=int(s.get("source_strip", s["id"])),
        vertices3d=_np.asarray(s["vertices3d"], dtype=_np.float64).reshape(-1, 3),
        vertices2d=_np.asarray(s["vertices2d"], dtype=_np.float64).reshape(-1, 2),
        triangles=_np.asarray(s["triangles"], dtype=_np.int32).reshape(-1, 3),
        uv=None if uv is None else _np.asarray(uv, dtype=_np.float64).reshape(-1, 2),
        boundary=list(s.get("boundary", [])),
    )


_PAPER = ("min_width_mm", "min_area_mm2", "scale", "max_pages", "allow_large_tolerance")


def run(V, F, tolerance="2%", height_mm=200, threads=0, config=None, name="model",
        **params) -> Result:
    """Runs the pipeline on numpy arrays V (n, 3) and F (m, 3) and returns a Result.

    tolerance: as on the command line ("2%" of the largest side, or "0.004" in model units).
    height_mm: the model's largest side on paper (ignored when scale is given).
    threads: 0 uses every core.
    config: a YAML file's path or YAML text; None: the builtin default.
    params: min_width_mm, min_area_mm2, scale (mm per model unit), max_pages,
      allow_large_tolerance, and any node parameter as "node.param" (e.g.
      **{"layout.page": "A3"}) or node__param (layout__page="A3").
    """
    paper, nodes = {}, {}
    for key, value in params.items():
        if key in _PAPER:
            paper[key] = value
        else:
            nodes[key.replace("__", ".", 1) if "." not in key else key] = value
    output = _papercraft.run(
        _np.asarray(V), _np.asarray(F), str(tolerance),
        None if height_mm is None else float(height_mm), int(threads),
        None if config is None else str(config), str(name), paper, nodes)
    files = output.files
    report = _json.loads(files["report.json"])
    strips = [_strip(s) for s in _json.loads(files["strips.json"])["strips"]] \
        if "strips.json" in files else []
    pieces = _json.loads(files["pieces.json"])["pieces"] if "pieces.json" in files else []
    return Result(name=output.name, report=report, strips=strips, pieces=pieces, _output=output)
