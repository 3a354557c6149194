"""`mpirun -n K python3 -m tetrakit.mpi check X.pvtu` prints what `tetrakit check X.pvtu`
prints (JSON field for field but the timings, the same exit code), on valid and corrupted
meshes cut into pieces written by meshio, with and without global ids, for K = 1, 2, 4
(more ranks than pieces included), and bad input is exit 2 naming the piece."""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import tetrakit

ROOT = Path(__file__).resolve().parents[3]
EXE = ROOT / "target" / "release" / "tetrakit"
MPI_ENV = {**os.environ, "OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}


def _need_mpi():
    missing = shutil.which("mpirun") is None
    try:
        import mpi4py  # noqa: F401
    except ImportError:
        missing = True
    if missing:
        if os.environ.get("TETRAKIT_REQUIRE_MPI"):
            pytest.fail("mpirun and mpi4py are required (TETRAKIT_REQUIRE_MPI is set)")
        pytest.skip("mpirun or mpi4py missing")


def _cases(tmp_path, meshio, count):
    """`count` partitioned meshes: Kuhn grids and random tetrahedralizations, valid or
    corrupted (a tetrahedron dropped, inverted, repeated, a small one nested inside
    another, a vertex moved), cut into 2-5 pieces in slabs or at random, written by
    meshio with or without GlobalNodeIds; every fifth with its pieces two to a file (a
    `.vtu` of several `Piece`s)."""
    rng = np.random.default_rng(46)
    out = []
    for k in range(count):
        src = tmp_path / f"src{k}.vtu"
        if k % 2 == 0:
            args = ["generate", "kuhn", "--size", str(2 + k % 3)]
        else:
            args = ["generate", "random-tetrahedralization", "--points", str(15 + k % 20), "--seed", str(k)]
        subprocess.run([str(EXE), *args, "-o", str(src)], check=True, capture_output=True)
        m = tetrakit.read(src)
        pts, tets = m.points.copy(), m.tets.copy()
        kind = k % 6
        t = int(rng.integers(len(tets)))
        if kind == 1:
            tets = np.delete(tets, t, axis=0)
        elif kind == 2:
            tets[t, [0, 1]] = tets[t, [1, 0]]
        elif kind == 3:
            tets = np.vstack([tets, tets[t]])
        elif kind == 4:
            c = pts[tets[t]]
            w = np.full((4, 4), 0.2) + 0.2 * np.eye(4)
            pts = np.vstack([pts, w @ c])
            n = len(pts) - 4
            tets = np.vstack([tets, [n, n + 1, n + 2, n + 3]])
        elif kind == 5:
            v = tets[t, 0]
            pts[v] += rng.uniform(-0.5, 0.5, 3)
        pieces = 2 + k % 4
        if k % 3 == 0:
            label = rng.integers(pieces, size=len(tets))
        else:
            x = pts[tets].mean(axis=1)[:, 0]
            label = np.minimum(((x - x.min()) / (np.ptp(x) + 1e-300) * pieces).astype(int), pieces - 1)
        index = tmp_path / f"case{k}.pvtu"
        sources = []
        for p in range(pieces):
            mine = tets[label == p]
            used = np.unique(mine) if len(mine) else np.zeros(0, int)
            local = {int(g): i for i, g in enumerate(used)}
            cells = np.array([[local[int(g)] for g in t4] for t4 in mine], dtype=np.int64).reshape(-1, 4)
            data = {"GlobalNodeIds": used.astype(np.int64)} if k % 4 < 2 else {}
            name = f"case{k}_{p}.vtu"
            meshio.write(tmp_path / name, meshio.Mesh(pts[used], [("tetra", cells)], point_data=data))
            sources.append(name)
        if k % 5 == 4:
            sources = _two_to_a_file(tmp_path, sources)
        index.write_text(
            '<?xml version="1.0"?>\n<VTKFile type="PUnstructuredGrid" version="0.1">\n'
            '<PUnstructuredGrid GhostLevel="0">\n'
            + "".join(f'<Piece Source="{s}"/>\n' for s in sources)
            + "</PUnstructuredGrid>\n</VTKFile>\n")
        out.append(index)
    return out


def _two_to_a_file(folder, sources):
    """The pieces of the files `sources` (in `folder`) put two to a file, in order: the
    new files' names."""
    grouped = []
    for g in range(0, len(sources), 2):
        texts = [(folder / s).read_text() for s in sources[g:g + 2]]
        body = "".join(t[t.index("<Piece "):t.rindex("</Piece>") + len("</Piece>")] for t in texts)
        head, tail = texts[0][:texts[0].index("<Piece ")], texts[0][texts[0].rindex("</Piece>") + 8:]
        name = sources[g].replace(".vtu", "_pair.vtu")
        (folder / name).write_text(head + body + tail)
        grouped.append(name)
    return grouped


def _strip(text):
    d = json.loads(text)
    for key in ("seconds", "parse_seconds"):
        d.pop(key, None)
    return d


def _cli(path, *flags):
    r = subprocess.run([str(EXE), "check", str(path), "--json", *flags], capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stderr
    return r.returncode, _strip(r.stdout)


def _mpirun(n, *args):
    cmd = ["mpirun", "-n", str(n), "--oversubscribe", sys.executable, *args]
    return subprocess.run(cmd, capture_output=True, text=True, env=MPI_ENV, timeout=600)


DRIVER = """
import json, sys
from mpi4py import MPI
from tetrakit import mpi
limit = int(sys.argv[3]) if len(sys.argv) > 3 else mpi.MESSAGE_LIMIT
out = []
for line in open(sys.argv[1]).read().splitlines():
    path, *flags = line.split()
    import io, contextlib
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        code = mpi.run(MPI.COMM_WORLD, ["check", path, "--json", *flags], limit=limit)
    out.append([code, buf.getvalue()])
if MPI.COMM_WORLD.rank == 0:
    open(sys.argv[2], "w").write(json.dumps(out))
"""


def test_mpirun_checks_as_tetrakit_check(tmp_path):
    """Many meshes in one `mpirun -n 2` (a driver calling `tetrakit.mpi.run` per file),
    and a few under `-n 1` and `-n 4`, each compared with `tetrakit check`; and under
    `-n 3` with at most 600 bytes an exchange, so that every message goes in rounds (as
    those past MPI's 2 GB do)."""
    _need_mpi()
    meshio = pytest.importorskip("meshio")
    cases = _cases(tmp_path, meshio, 120)
    flags = [[], ["--convex"], ["--manifold", "--reorient"]]
    jobs = [(c, flags[k % 3]) for k, c in enumerate(cases)]
    (tmp_path / "jobs.txt").write_text("".join(f"{c} {' '.join(f)}\n" for c, f in jobs))
    (tmp_path / "driver.py").write_text(DRIVER)
    invalid = 0
    for n, take, limit in ((2, len(jobs), []), (1, 12, []), (4, 12, []), (3, 15, ["600"])):
        (tmp_path / "jobs.txt").write_text("".join(f"{c} {' '.join(f)}\n" for c, f in jobs[:take]))
        r = _mpirun(n, str(tmp_path / "driver.py"), str(tmp_path / "jobs.txt"), str(tmp_path / "out.json"),
                    *limit)
        assert r.returncode == 0, r.stderr
        got = json.loads((tmp_path / "out.json").read_text())
        assert len(got) == take
        for (case, f), (code, text) in zip(jobs[:take], got):
            want_code, want = _cli(case, *f)
            assert (code, _strip(text)) == (want_code, want), (n, case, f)
            invalid += want_code
    assert invalid >= 40


def test_python_m_tetrakit_mpi(tmp_path):
    """The entry point itself: text and JSON as `tetrakit check`, the exit code of a NO,
    and bad input (a piece missing, a piece outside the folder, not a .pvtu): exit 2 and
    one line naming the file."""
    _need_mpi()
    index = tmp_path / "k.pvtu"
    subprocess.run([str(EXE), "generate", "kuhn", "--size", "3", "--corrupt", "add-overlap",
                    "-o", str(index), "--pieces", "3"], check=True, capture_output=True)
    want = subprocess.run([str(EXE), "check", str(index)], capture_output=True, text=True)
    assert want.returncode == 1
    for n in (1, 2, 4):
        r = _mpirun(n, "-m", "tetrakit.mpi", "check", str(index))
        assert r.returncode == 1, r.stderr
        strip = lambda s: [line.split(" [")[0] for line in s.splitlines()]  # noqa: E731
        assert strip(r.stdout) == strip(want.stdout)
    text = index.read_text()
    for bad, named in ((text.replace("k_1.vtu", "k_9.vtu"), "k_9.vtu"),
                       (text.replace("k_1.vtu", "../k_1.vtu"), "k.pvtu:")):
        index.write_text(bad)
        r = _mpirun(2, "-m", "tetrakit.mpi", "check", str(index), "--json")
        lines = r.stderr.strip().splitlines()
        assert r.returncode == 2 and r.stdout == "", r
        assert len([x for x in lines if x.startswith("tetrakit:")]) == 1 and named in r.stderr, r.stderr
    r = _mpirun(2, "-m", "tetrakit.mpi", "check", str(tmp_path / "k_0.vtu"))
    assert r.returncode == 2 and "checks a .pvtu" in r.stderr


def test_mpirun_writes_the_pieces_tetrakit_check_writes(tmp_path):
    """`--output P.pvtu` under `mpirun -n 1, 2, 3`: each rank writes its pieces with their
    problem fields, the same bytes as `tetrakit check --output`; a path that cannot be
    written, or not a .pvtu, is exit 2 with one line."""
    _need_mpi()
    index = tmp_path / "k.pvtu"
    subprocess.run([str(EXE), "generate", "kuhn", "--size", "3", "--corrupt", "add-overlap",
                    "-o", str(index), "--pieces", "3"], check=True, capture_output=True)
    one = tmp_path / "one.pvtu"
    r = subprocess.run([str(EXE), "check", str(index), "--output", str(one)], capture_output=True)
    assert r.returncode == 1, r.stderr
    for n in (1, 2, 3):
        many = tmp_path / f"many{n}.pvtu"
        r = _mpirun(n, "-m", "tetrakit.mpi", "check", str(index), "--output", str(many))
        assert r.returncode == 1, r.stderr
        for p in range(3):
            a = (tmp_path / f"one_{p}.vtu").read_bytes()
            assert a == (tmp_path / f"many{n}_{p}.vtu").read_bytes(), (n, p)
            assert b'Name="problem"' in a
        assert one.read_text().replace("one_", "X_") == many.read_text().replace(f"many{n}_", "X_")
    r = _mpirun(2, "-m", "tetrakit.mpi", "check", str(index), "--output", str(tmp_path / "no" / "p.pvtu"))
    lines = [x for x in r.stderr.splitlines() if x.startswith("tetrakit:")]
    assert r.returncode == 2 and len(lines) == 1 and "p_0.vtu" in lines[0], r.stderr
    r = _mpirun(2, "-m", "tetrakit.mpi", "check", str(index), "--output", str(tmp_path / "p.vtu"))
    assert r.returncode == 2 and "as a .pvtu" in r.stderr
