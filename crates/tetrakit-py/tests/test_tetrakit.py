"""Tests of the Python package: results against the CLI on the same data, bad input,
meshio round trips, the GIL, time limits and Ctrl-C."""

import json
import re
import os
import signal
import subprocess
import threading
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import tetrakit

ROOT = Path(__file__).resolve().parents[3]
UNIT_TET = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
# Timing fields, file names and file contents (other_cells: the non-tet cells of a mesh
# file) the CLI prints that a call on arrays has no use for.
CLI_ONLY = {"seconds", "parse_seconds", "algorithm_seconds", "time_limit",
            "faces_beside_not_read", "output", "svg", "tets", "other_cells", "tris", "proof"}


def cli(*args):
    """The CLI's JSON for `args` (the release binary that `cargo test --release` builds)."""
    exe = Path(os.environ.get("TETRAKIT_BIN", ROOT / "target" / "release" / "tetrakit"))
    assert exe.exists(), f"{exe} is missing: run `cargo build --release` first"
    out = subprocess.run([str(exe), *map(str, args), "--json"], capture_output=True, text=True)
    assert out.returncode in (0, 1, 3), out.stderr
    return json.loads(out.stdout)


def write_json(path, **arrays):
    path.write_text(json.dumps({k: np.asarray(v).tolist() for k, v in arrays.items()}))
    return path


def assert_same_fields(result, cli_json, ignore=()):
    """Every field the CLI prints is a field of the result, with the same value where it
    is a number, a string or a boolean (counts that became arrays: same length)."""
    for key, value in cli_json.items():
        if key in CLI_ONLY or key in ignore:
            continue
        assert hasattr(result, key), f"{type(result).__name__} lacks the CLI field {key!r}"
        mine = getattr(result, key)
        if isinstance(mine, np.ndarray) and isinstance(value, int):
            assert len(mine) == value, key
        elif isinstance(value, (bool, int, str)):
            assert mine == value, (key, mine, value)


def kuhn(k):
    """A k×k×k grid of cubes, six tetrahedra each (the Kuhn triangulation)."""
    g = np.arange(k + 1)
    pts = np.array([[x, y, z] for x in g for y in g for z in g], dtype=float)
    idx = lambda x, y, z: (x * (k + 1) + y) * (k + 1) + z
    tets = []
    perms = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for x in range(k):
        for y in range(k):
            for z in range(k):
                for p in perms:
                    c = [x, y, z]
                    path = [idx(*c)]
                    for axis in p:
                        c[axis] += 1
                        path.append(idx(*c))
                    tets.append(path)
    return pts, tetrakit.check(pts, np.array(tets), reorient=True).tets


# --- check -----------------------------------------------------------------------------

def test_check_agrees_with_the_cli_on_a_valid_and_a_corrupt_mesh(tmp_path):
    pts, tets = kuhn(3)
    for name, t in [("ok", tets), ("bad", np.delete(tets, 7, axis=0))]:
        r = tetrakit.check(pts, t, convex=True)
        c = cli("check", write_json(tmp_path / f"{name}.json", points=pts, tets=t), "--convex")
        assert_same_fields(r, c, ignore={"problems", "witness"})
        assert r.problems == c["problems"]
    assert tetrakit.check(pts, tets).valid
    bad = tetrakit.check(pts, np.delete(tets, 7, axis=0), convex=True)
    assert not bad.valid and bad.witness["kind"] == bad.problems[0]["kind"]


def test_check_fields_mark_the_bad_tets_with_their_codes():
    pts, tets = kuhn(2)
    t = tets.copy()
    t[5] = t[5][[1, 0, 2, 3]]
    r = tetrakit.check(pts, t)
    code = r.problem_codes["inverted"]
    assert r.cell_problems.shape == (len(t),) and r.point_problems.shape == (len(pts),)
    assert r.cell_problems[5] == code
    assert np.count_nonzero(r.cell_problems == code) == 1
    assert set(np.flatnonzero(r.point_problems)) >= set(t[5])
    turned = tetrakit.check(pts, t, reorient=True)
    assert turned.valid and turned.reoriented == 1
    assert (turned.tets[5] != t[5]).any() and turned.cell_problems.max() == 0


@pytest.mark.parametrize("points, tets, message", [
    (UNIT_TET, [[0, 1, 2, 4]], "tets[0] names vertex 4, but points are numbered 0..=3"),
    (UNIT_TET, [[0, 1, 2, -1]], "tets[0] names vertex -1, but points are numbered 0..=3"),
    (np.where(np.eye(4, 3) > 0, np.nan, 0.0), [[0, 1, 2, 3]], "point 0 has coordinate NaN, which is not finite"),
    (UNIT_TET, [[0, 1, 2]], "tets has shape (1, 3): expected (1, 4)"),
    (UNIT_TET, [[0.0, 1.0, 2.0, 3.0]], "tets has dtype float64"),
    (UNIT_TET[:, :1], [[0, 1, 2, 3]], "points has shape (4, 1)"),
    (UNIT_TET, [], "no tetrahedra to check"),
    (np.zeros((0, 3)), [[0, 1, 2, 3]], "no points"),
])
def test_bad_arrays_are_a_value_error_naming_the_row(points, tets, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        tetrakit.check(points, tets)


def test_coincident_points_matter_only_as_tetrahedron_vertices():
    """A point no tetrahedron uses may sit on another (Gmsh writes such nodes); two
    tetrahedron vertices at one place are a NO naming both (pieces never merged)."""
    assert tetrakit.check(np.vstack([UNIT_TET, UNIT_TET[:1]]), [[0, 1, 2, 3]]).valid
    pts = np.vstack([UNIT_TET, [[1, 1, 1], [1, 0, 0]]])
    r = tetrakit.check(pts, [[0, 1, 2, 3], [5, 4, 2, 3]])
    kinds = [p["kind"] for p in r.problems]
    assert not r.valid and "coincident_vertices" in kinds, r.problems
    p = r.problems[kinds.index("coincident_vertices")]
    assert p["vertices"] == [1, 5] and p["tets"] == [0, 1]


def test_bad_input_messages_are_the_file_readers(tmp_path):
    c = subprocess.run([str(ROOT / "target/release/tetrakit"), "check",
                        str(write_json(tmp_path / "b.json", points=UNIT_TET, tets=[[0, 1, 2, 9]]))],
                       capture_output=True, text=True)
    assert c.returncode == 2
    with pytest.raises(ValueError) as e:
        tetrakit.check(UNIT_TET, [[0, 1, 2, 9]])
    assert str(e.value) in c.stderr


# --- detect, contains, constrained, mintetra, tetrahedralize --------------------------------------------------

def test_detect_yes_and_no_match_the_cli(tmp_path):
    pts, tets = kuhn(2)
    edges = np.unique(np.sort(np.concatenate([tets[:, [i, j]] for i in range(4) for j in range(i + 1, 4)]), axis=1), axis=0)
    for name, e in [("yes", edges), ("no", edges[1:])]:
        r = tetrakit.detect(pts, e)
        c = cli("detect", write_json(tmp_path / f"{name}.json", points=pts, segments=e))
        assert_same_fields(r, c, ignore={"witness"})
    yes = tetrakit.detect(pts, edges)
    assert yes.verdict == "yes" and tetrakit.check(pts, yes.cells, convex=True).valid
    no = tetrakit.detect(pts, edges[1:])
    assert no.verdict == "no" and no.witness["kind"] and len(no.cells) == 0


def test_contains_and_constrained_match_the_cli(tmp_path):
    pts, tets = kuhn(1)
    edges = np.unique(np.sort(np.concatenate([tets[:, [i, j]] for i in range(4) for j in range(i + 1, 4)]), axis=1), axis=0)
    cube = [tuple(p) for p in pts]
    other = [cube.index(a) for a in [(0, 0, 0), (1, 1, 1)]]  # the long diagonal is an edge of Kuhn's
    extra = np.vstack([edges, [[cube.index((1, 0, 0)), cube.index((0, 1, 1))]]])  # a second long diagonal
    cases = [("contains", extra, "yes"), ("contains", edges[1:], "no"),
             ("constrained", [other], "yes"),
             ("constrained", [other, [cube.index((1, 0, 0)), cube.index((0, 1, 1))]], "no")]
    for k, (command, segs, verdict) in enumerate(cases):
        r = getattr(tetrakit, command)(pts, segs)
        c = cli(command, write_json(tmp_path / f"{k}.json", points=pts, segments=segs))
        assert_same_fields(r, c)
        assert r.verdict == verdict, (command, r)
        if verdict == "yes":
            assert r.certified and r.cells.shape == (r.tetrahedra, 4)
            assert tetrakit.check(pts, r.cells, convex=True).valid
            used = {tuple(sorted((t[i], t[j]))) for t in r.cells.tolist() for i in range(4) for j in range(i + 1, 4)}
            given = {tuple(sorted(e)) for e in np.asarray(segs).tolist()}
            assert used <= given if command == "contains" else given <= used
        else:
            assert r.witness["kind"] == c["witness"]["kind"] and len(r.cells) == 0
    m = tetrakit.constrained(pts, [other], minimal=True)  # the long diagonal rules out the 5-tet cube
    assert m.minimum and m.tetrahedra == 6


def test_planar_contains_gives_triangles_and_bad_segments_are_a_value_error(tmp_path):
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    r = tetrakit.contains(square, [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]])
    assert r.planar and r.triangles == 2 and r.cells.tolist() == [[0, 1, 2], [0, 2, 3]]
    bad = write_json(tmp_path / "bad.json", points=square, segments=[[0, 7]])
    c = subprocess.run([str(ROOT / "target/release/tetrakit"), "constrained", str(bad)],
                       capture_output=True, text=True)
    assert c.returncode == 2
    with pytest.raises(ValueError) as e:
        tetrakit.constrained(square, [[0, 7]])
    assert str(e.value) in c.stderr


def bipyramid(k):
    ring = [[np.cos(2 * np.pi * i / k), np.sin(2 * np.pi * i / k), 0.0] for i in range(k)]
    pts = np.array(ring + [[0, 0, 1], [0, 0, -1]])
    faces = [[i, (i + 1) % k, k] for i in range(k)] + [[(i + 1) % k, i, k + 1] for i in range(k)]
    return pts, np.array(faces)


def test_mintetra_and_tetrahedralize_match_the_cli(tmp_path):
    pts, faces = bipyramid(6)
    f = write_json(tmp_path / "bp.json", points=pts, faces=faces)
    m = tetrakit.mintetra(pts, faces)
    assert_same_fields(m, cli("mintetra", f), ignore={"polar_edges"})
    assert m.verdict == "yes" and m.tetrahedra == len(m.tets) == len(pts) - 2
    t = tetrakit.tetrahedralize(pts, faces, minimal=True)
    assert_same_fields(t, cli("tetrahedralize", f, "--minimal"))
    assert t.minimum == m.tetrahedra


def test_schonhardt_is_a_certified_no():
    a = [[np.cos(2 * np.pi * i / 3), np.sin(2 * np.pi * i / 3)] for i in range(3)]
    tw = np.radians(30)
    top = [[np.cos(2 * np.pi * i / 3 + tw), np.sin(2 * np.pi * i / 3 + tw)] for i in range(3)]
    pts = np.array([p + [0.0] for p in a] + [p + [1.0] for p in top])
    faces = [[0, 2, 1], [3, 4, 5]]
    for i in range(3):
        j = (i + 1) % 3
        faces += [[i, j, 3 + j], [i, 3 + j, 3 + i]]
    r = tetrakit.tetrahedralize(pts, faces)
    assert r.verdict == "no" and r.witness is not None and len(r.tets) == 0


def test_a_polyhedron_that_is_not_simple_is_a_value_error():
    pts, faces = bipyramid(5)
    with pytest.raises(ValueError, match="not a simple polyhedron"):
        tetrakit.mintetra(pts, faces[:-1])


# --- shell -----------------------------------------------------------------------------

def sphere(n, r, seed):
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return r * v / np.linalg.norm(v, axis=1, keepdims=True)


def test_shell_is_certified_within_the_bound_and_matches_the_cli(tmp_path):
    outer, inner = sphere(60, 2.0, 1), sphere(40, 1.0, 2)
    for method in ("cap", "bigcap"):
        r = tetrakit.shell(outer, inner, method=method)
        c = cli("shell", write_json(tmp_path / "o.json", points=outer),
                write_json(tmp_path / "i.json", points=inner), "--method", method)
        assert_same_fields(r, c)
        assert r.verdict == "yes" and r.steiner_points == 0 and r.tetrahedra <= r.bound
        assert r.tets.shape == (r.tetrahedra, 4) and r.points.shape == (r.n, 3)


def test_shell_errors_name_the_problem():
    with pytest.raises(ValueError, match="outside the outer hull"):
        tetrakit.shell(sphere(30, 1.0, 1), sphere(20, 2.0, 2))
    with pytest.raises(ValueError, match="method 'fast'"):
        tetrakit.shell(sphere(30, 2.0, 1), sphere(20, 1.0, 2), method="fast")
    with pytest.raises(ValueError, match="planar"):
        tetrakit.shell(sphere(30, 2.0, 1)[:, :2], sphere(20, 1.0, 2))


# --- planar ----------------------------------------------------------------------------

def test_skeleton_mwt_and_keil_match_the_cli(tmp_path):
    pts = np.random.default_rng(3).random((300, 2))
    f = write_json(tmp_path / "p.json", points=pts)
    for beta in ("1", "3/2", "0.7"):
        s = tetrakit.skeleton(pts, beta)
        assert_same_fields(s, cli("skeleton", f, "--beta", beta))
    assert len(tetrakit.skeleton(pts, Fraction(3, 2)).edges) == len(tetrakit.skeleton(pts, "1.5").edges)
    m = tetrakit.mwt(pts)
    assert_same_fields(m, cli("mwt", f))
    lo, hi = m.weight_interval
    w = np.linalg.norm(pts[m.edges[:, 0]] - pts[m.edges[:, 1]], axis=1).sum()
    assert lo - 1e-9 <= w <= hi + 1e-9
    assert len(m.triangles) == len(m.edges) - len(pts) + 1  # Euler
    k = tetrakit.keil("1.156")
    assert_same_fields(k, cli("keil", "--beta", "1.156"))
    assert k.refutes_keil and k.sites.shape[1] == 2


def test_planar_inputs_are_checked():
    with pytest.raises(ValueError, match="has z = 1"):
        tetrakit.mwt(UNIT_TET)
    with pytest.raises(ValueError, match="beta"):
        tetrakit.skeleton(UNIT_TET[1:, :2], "x")
    with pytest.raises(ValueError, match="time_limit"):
        tetrakit.mwt(UNIT_TET[1:, :2], time_limit=-1)
    with pytest.raises(ValueError, match=re.escape("points 0 and 3 coincide at [0.0, 0.0, 0.0]") + "$"):
        tetrakit.mwt(UNIT_TET[:, :2])


# --- time limits, the GIL, Ctrl-C --------------------------------------------------------

def test_out_of_time_gives_certified_bounds():
    pts = np.random.default_rng(4).random((20000, 2))
    m = tetrakit.mwt(pts, time_limit=0)
    assert m.verdict == "undecided" and m.lower_bound <= m.upper_bound
    assert len(m.triangles) > 0


def test_work_releases_the_gil():
    pts = np.random.default_rng(5).random((30000, 2))
    done, ticks = threading.Event(), [0]
    worker = threading.Thread(target=lambda: (tetrakit.mwt(pts), done.set()))
    worker.start()
    while not done.is_set():
        ticks[0] += 1
    worker.join()
    # Holding the GIL for the whole call would leave this thread a handful of turns.
    assert ticks[0] > 10000


def test_ctrl_c_stops_the_work():
    pts = np.random.default_rng(6).random((4000, 2))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        tetrakit.skeleton(pts, "0.05")  # minutes of work without the stop
    timer.join()


# --- meshio ------------------------------------------------------------------------------

def test_meshio_round_trip(tmp_path):
    meshio = pytest.importorskip("meshio")
    pts, tets = kuhn(3)
    mesh = meshio.Mesh(pts, [("tetra", tets)])
    p, t = tetrakit.from_meshio(mesh)
    assert tetrakit.check(p, t, convex=True).valid
    # A result written with meshio, read back by meshio and by the CLI: one verdict.
    r = tetrakit.shell(sphere(50, 2.0, 7), sphere(30, 1.0, 8))
    variants = [("vtu", {}), ("vtu", {"binary": False}), ("vtu", {"compression": None}),
                ("vtk", {}), ("vtk", {"binary": False}), ("mesh", {}),
                ("msh", {"file_format": "gmsh22", "binary": False}), ("msh", {"file_format": "gmsh"})]
    for k, (ext, opts) in enumerate(variants):
        path = tmp_path / f"shell{k}.{ext}"
        meshio.write(path, meshio.Mesh(r.points, [("tetra", r.tets)]), **opts)
        back = tetrakit.check(*tetrakit.from_meshio(meshio.read(path)))
        assert back.valid and back.tetrahedra == r.tetrahedra
        c = cli("check", path)
        assert (c["verdict"], c["tetrahedra"]) == ("yes", r.tetrahedra), (ext, opts)
    hexes = meshio.Mesh(pts[:8], [("hexahedron", [list(range(8))])])
    with pytest.raises(ValueError, match="hexahedron 1"):
        tetrakit.from_meshio(hexes)
