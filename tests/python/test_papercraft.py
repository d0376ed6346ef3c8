"""The Python module against the command line: same loader, same pipeline, same files."""

import json
import math
import os
import subprocess
import threading

import numpy as np
import pytest

import papercraft

BINARY = os.environ.get("PAPERCRAFT_BINARY", "papercraft")


def torus(major=2.0, minor=0.7, rings=24, sides=12):
    V = []
    for i in range(rings):
        u = 2 * math.pi * i / rings
        for j in range(sides):
            w = 2 * math.pi * j / sides
            r = major + minor * math.cos(w)
            V.append((r * math.cos(u), r * math.sin(u), minor * math.sin(w)))
    F = []
    for i in range(rings):
        for j in range(sides):
            a = i * sides + j
            b = ((i + 1) % rings) * sides + j
            c = ((i + 1) % rings) * sides + (j + 1) % sides
            d = i * sides + (j + 1) % sides
            F += [(a, b, c), (a, c, d)]
    return np.array(V, dtype=np.float64), np.array(F, dtype=np.int64)


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        for p in V:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in F:
            f.write("3 %d %d %d\n" % tuple(t))


def test_arrays_give_the_command_lines_result(tmp_path):
    V, F = torus()
    result = papercraft.run(V, F, tolerance="2%", threads=2, name="torus")
    assert result.certified
    assert result.pages >= 1
    assert len(result.strips) == result.report["result"]["flat_strips"]
    strip = result.strips[0]
    assert strip.vertices3d.shape[1] == 3 and strip.vertices2d.shape[1] == 2
    assert strip.triangles.shape[1] == 3 and strip.triangles.max() < len(strip.vertices3d)
    assert all(edge["kind"] == "seam" for edge in strip.seams)
    assert len(result.pieces) >= len(result.strips)

    write_off(tmp_path / "torus.off", V, F)
    subprocess.run([BINARY, "run", str(tmp_path / "torus.off"), "--tolerance", "2%",
                    "--threads", "2", "--out", str(tmp_path / "cli"), "-q"], check=True,
                   stdout=subprocess.DEVNULL)
    cli = json.loads((tmp_path / "cli" / "torus" / "report.json").read_text())
    assert result.report["result"]["strips_3d"] == cli["result"]["strips_3d"]
    assert result.report["result"]["flat_strips"] == cli["result"]["flat_strips"]
    assert result.hausdorff_bound == cli["result"]["hausdorff_bound"]
    assert result.files["strips.json"] == (tmp_path / "cli" / "torus" / "strips.json").read_bytes()
    assert result.effort == cli["effort"]
    assert result.effort["things_to_cut"] == len(result.pieces) + result.effort["joining_strips"]


def test_load_gives_the_loaded_mesh(tmp_path):
    V, F = torus()
    write_off(tmp_path / "t.off", V, F)
    V2, F2 = papercraft.load(tmp_path / "t.off")
    assert V2.dtype == np.float64 and V2.shape == V.shape
    assert F2.shape == F.shape and np.issubdtype(F2.dtype, np.integer)
    assert np.array_equal(V2, V) and np.array_equal(F2, F)


def test_run_writes_no_file(tmp_path, monkeypatch):
    # Neither in the working folder nor in the temporary folder: the arrays go in and the files
    # come back in memory.
    (tmp_path / "cwd").mkdir()
    (tmp_path / "tmp").mkdir()
    monkeypatch.chdir(tmp_path / "cwd")
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    V, F = torus(rings=12, sides=8)
    result = papercraft.run(V, F, name="small", threads=2)
    assert result.certified and result.files["pattern.pdf"].startswith(b"%PDF-")
    assert result.report["input"]["path"] == "<arrays>"
    assert list((tmp_path / "cwd").iterdir()) == [] and list((tmp_path / "tmp").iterdir()) == []


def test_no_file_is_left_and_write_makes_a_folder_summary_reads(tmp_path):
    V, F = torus(rings=12, sides=8)
    result = papercraft.run(V, F, name="small")
    assert "pattern.pdf" in result.files and "report.json" in result.files
    folder = result.write(tmp_path / "out")
    for name in ("pattern.pdf", "strips.json", "pieces.json", "report.json", "approximation.obj"):
        assert os.path.isfile(os.path.join(folder, name)), name
    assert (tmp_path / "out" / "run.json").is_file()
    summary = subprocess.run([BINARY, "summary", str(tmp_path / "out")], capture_output=True,
                             text=True)
    assert summary.returncode == 0, summary.stderr
    assert "small" in summary.stdout
    # The summary times the run, not the write: about the seconds the run took.
    run = json.loads((tmp_path / "out" / "run.json").read_text())
    assert run["wall_seconds"] >= 0.8 * run["results"][0]["wall_seconds"] > 0
    assert run["models_per_minute"] <= 60 / (0.8 * run["results"][0]["wall_seconds"])
    rows = json.loads((tmp_path / "out" / "batch.json").read_text())["results"]
    assert [r["name"] for r in rows] == ["small"] and rows[0]["status"] == "ok"


@pytest.mark.parametrize("V, F, words", [
    (np.array([[0, 0, 0], [1, 0, 0], [math.nan, 1, 0]]), np.array([[0, 1, 2]]), "vertex 2 is not finite"),
    (np.zeros((3, 2)), np.array([[0, 1, 2]]), "(n, 3)"),
    (np.eye(3), np.array([[0, 1, 3]]), "out of range"),
    (np.eye(3), np.array([[0, 1, -1]]), "out of range"),
    (np.eye(3), np.array([[0.0, 1.0, 2.0]]), "integers"),
    (np.eye(3), np.array([0, 1, 2]), "(m, 3)"),
    (np.eye(3), np.zeros((0, 3), dtype=int), "no faces"),
])
def test_bad_arrays_raise_value_error(V, F, words):
    with pytest.raises(ValueError, match=__import__("re").escape(words)):
        papercraft.run(V, F)


def test_the_loaders_errors_are_value_errors(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(ValueError, match="bad.off"):
        papercraft.load(bad)
    with pytest.raises(OSError, match="no such file"):
        papercraft.load(tmp_path / "missing.obj")
    # A mesh the loader refuses (a face written twice, repair off): the loader's message, the
    # mesh named <arrays>.
    with pytest.raises(ValueError, match="<arrays>.*duplicate"):
        papercraft.run(np.eye(3), np.array([[0, 1, 2], [0, 1, 2]]), **{"load.repair": False})


def test_config_and_node_parameters(tmp_path):
    V, F = torus(rings=12, sides=8)
    a3 = papercraft.run(V, F, layout__page="A3")
    assert "A3" in a3.report["config"]["text"]
    with pytest.raises(ValueError, match="nodes"):
        papercraft.run(V, F, config="description: x\nnodes: []\n")
    with pytest.raises(ValueError, match="unknown"):
        papercraft.run(V, F, nonsense=1)
    with pytest.raises(ValueError, match="tolerance"):
        papercraft.run(V, F, tolerance="two percent")


def test_threads_in_python_run_side_by_side():
    V, F = torus(rings=16, sides=10)
    results = [None, None]

    def work(i):
        results[i] = papercraft.run(V, F, threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0].files["strips.json"] == results[1].files["strips.json"]
    assert results[0].certified and results[1].certified
