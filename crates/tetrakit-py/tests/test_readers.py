"""The readers against the tools that write mesh files: Gmsh's own tutorial and demo
geometries meshed by Gmsh and saved in every format and variant Gmsh and meshio write,
each read by tetrakit and by meshio (points, tetrahedra and the check's verdict must
agree), and one mesh with coordinates the exact predicates cannot take, written by
meshio in every format tetrakit reads, refused by every reader."""

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import tetrakit

meshio = pytest.importorskip("meshio")

ROOT = Path(__file__).resolve().parents[3]
DOCS = Path("/usr/share/doc/gmsh-doc/doc/gmsh")
# Geometries with volumes: physical groups (t2, t5, t18), several volumes and boolean
# operations (t16, compsolid, primitives), internal surfaces (baffles), periodicity (t18).
GEOMETRIES = ["tutorial/t2.geo", "tutorial/t5.geo", "tutorial/t16.geo", "tutorial/t18.geo",
              "demos/boolean/compsolid.geo", "demos/boolean/primitives.geo",
              "demos/boolean/baffles.geo"]
# Gmsh's writers: (file name, gmsh options).
GMSH_FORMATS = [
    ("msh41.msh", ["-format", "msh41"]),
    ("msh41b.msh", ["-format", "msh41", "-bin"]),
    ("msh22.msh", ["-format", "msh22"]),
    ("msh22b.msh", ["-format", "msh22", "-bin"]),
    ("all.vtk", ["-format", "vtk", "-save_all"]),
    ("all41.msh", ["-format", "msh41", "-save_all"]),
    ("all22b.msh", ["-format", "msh22", "-bin", "-save_all"]),
    ("gmsh.vtk", ["-format", "vtk"]),
    ("gmsh.mesh", ["-format", "mesh"]),
    ("o2.msh", ["-format", "msh41", "-order", "2"]),
]
# meshio's writers: (file name, meshio format, keyword arguments). (Gmsh 4.1 comes from
# Gmsh itself: meshio's 4.1 writer needs Gmsh's entity data, which its medit writer
# cannot take.)
MESHIO_FORMATS = [
    ("ascii.vtu", "vtu", {"binary": False}),
    ("plain.vtu", "vtu", {"binary": True, "compression": None}),
    ("zlib.vtu", "vtu", {"binary": True, "compression": "zlib"}),
    ("lzma.vtu", "vtu", {"binary": True, "compression": "lzma"}),
    ("ascii.vtk", "vtk", {"binary": False}),
    ("binary.vtk", "vtk", {"binary": True}),
    ("ascii42.vtk", "vtk42", {"binary": False}),
    ("binary42.vtk", "vtk42", {"binary": True}),
    ("medit.mesh", "medit", {}),
    ("g22.msh", "gmsh22", {"binary": False}),
    ("g22b.msh", "gmsh22", {"binary": True}),
    ("tg.ele", "tetgen", {}),
]


def need_gmsh():
    if shutil.which("gmsh") and DOCS.exists():
        return
    if os.environ.get("TETRAKIT_REQUIRE_GMSH"):
        pytest.fail("gmsh and gmsh-doc are required (TETRAKIT_REQUIRE_GMSH is set)")
    pytest.skip("gmsh or gmsh-doc is not installed")


def source(geo: str, into: Path) -> Path:
    """The geometry in `into`, unzipped, with the files it includes beside it."""
    for f in (DOCS / geo).parent.iterdir():
        if f.suffix == ".gz" and f.name.endswith(".geo.gz"):
            (into / f.name[:-3]).write_bytes(__import__("gzip").decompress(f.read_bytes()))
        elif f.suffix == ".geo":
            shutil.copy(f, into / f.name)
    return into / Path(geo).name


def meshio_tets(m):
    """The tetrahedra of a meshio mesh, in file order (corners of quadratic ones)."""
    blocks = [np.asarray(b.data)[:, :4] for b in m.cells if b.type in ("tetra", "tetra10")]
    return np.concatenate(blocks) if blocks else np.zeros((0, 4), dtype=np.int64)


def corners(points, tets):
    """Each tetrahedron as its four corners' coordinates (12 numbers, in its order), the
    rows sorted: the same for two files of one mesh whatever their node numbering."""
    rows = np.asarray(points, dtype=float)[np.asarray(tets)].reshape(len(tets), 12)
    return rows[np.lexsort(rows.T[::-1])]


def same_mesh(path: Path):
    """tetrakit and meshio read the same points and tetrahedra from `path`, and the
    check of the file gives the verdict of the check of meshio's arrays. Where meshio
    cannot read a file Gmsh wrote (it refuses physical tags on some elements only, as
    Gmsh writes them with `-save_all`), the tetrahedra, by their corners' coordinates,
    are those meshio reads from the VTK file Gmsh wrote with the same options."""
    mine = tetrakit.read(path)
    try:
        theirs = meshio.read(path)
    except ValueError:
        assert path.name.startswith("all"), path.name
        twin = meshio.read(path.parent / "all.vtk")
        assert np.array_equal(corners(mine.points, mine.tets),
                              corners(twin.points, meshio_tets(twin))), path.name
        return mine
    assert np.array_equal(mine.points, np.asarray(theirs.points, dtype=float)), path.name
    assert np.array_equal(mine.tets, meshio_tets(theirs)), path.name
    of_file = tetrakit.check(mine.points, mine.tets).verdict
    of_arrays = tetrakit.check(np.asarray(theirs.points, float), meshio_tets(theirs)).verdict
    assert of_file == of_arrays, path.name
    return mine


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    """Every geometry meshed by Gmsh and saved in every format (directory per geometry)."""
    need_gmsh()
    root = tmp_path_factory.mktemp("corpus")
    made = {}
    for geo in GEOMETRIES:
        d = root / Path(geo).stem
        d.mkdir()
        g = source(geo, d)
        files = []
        for name, opts in GMSH_FORMATS:
            out = d / name
            run = subprocess.run(["gmsh", "-3", "-clscale", "2", str(g), "-o", str(out), *opts],
                                 capture_output=True, text=True, timeout=300)
            assert run.returncode == 0, run.stdout + run.stderr
            files.append(out)
        read = meshio.read(d / "msh41.msh")
        base = meshio.Mesh(read.points, read.cells)
        # meshio's TetGen writer repeats the header per block: one block for it.
        one = meshio.Mesh(read.points, [("tetra", meshio_tets(read))])
        for name, fmt, kw in MESHIO_FORMATS:
            out = d / name
            meshio.write(out, one if fmt == "tetgen" else base, file_format=fmt, **kw)
            files.append(out)
        made[geo] = files
    return made


@pytest.mark.parametrize("geo", GEOMETRIES)
def test_every_format_reads_as_meshio_reads_it(corpus, geo):
    counts = set()
    for f in corpus[geo]:
        counts.add(len(same_mesh(f).tets))
    # Every format carries the same tetrahedra (quadratic ones by their corners).
    assert len(counts) == 1, (geo, counts)


def test_sparse_node_tags_are_named_by_their_tags(tmp_path):
    """Gmsh leaves gaps in node tags (here: renumbered by hand); problems name the tags."""
    text = ("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n10 0 0 0\n20 1 0 0\n"
            "30 0 1 0\n40 0 0 1\n$EndNodes\n$Elements\n1\n7 4 2 1 1 10 30 20 40\n$EndElements\n")
    p = tmp_path / "sparse.msh"
    p.write_text(text)
    m = tetrakit.read(p)
    assert m.point_labels == [10, 20, 30, 40] and m.tets.tolist() == [[0, 2, 1, 3]]
    assert meshio_tets(meshio.read(p)).tolist() == m.tets.tolist()
    out = subprocess.run([str(ROOT / "target/release/tetrakit"), "check", str(p)],
                         capture_output=True, text=True)
    assert out.returncode == 1 and "T7" in out.stdout and "#30" in out.stdout, out.stdout


OUT_OF_RANGE = [1e200, 1e-200, float("nan"), float("inf"), 5e-324]


@pytest.mark.parametrize("value", OUT_OF_RANGE, ids=["1e200", "1e-200", "nan", "inf", "denormal"])
def test_no_reader_lets_a_coordinate_out_of_range_through(tmp_path, value):
    """The same mesh, one coordinate out of the exact range, in every format meshio
    writes that tetrakit reads: every reader refuses it with exit 2 naming the file."""
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    pts[3, 2] = value
    mesh = meshio.Mesh(pts, [("tetra", np.array([[0, 1, 2, 3]]))])
    formats = MESHIO_FORMATS + [("g41.msh", "gmsh", {"binary": False}),
                                ("g41b.msh", "gmsh", {"binary": True}),
                                ("m.obj", "obj", {}), ("m.off", "off", {}),
                                ("m.stl", "stl", {"binary": False}),
                                ("b.stl", "stl", {"binary": True})]
    exe = str(ROOT / "target/release/tetrakit")
    for name, fmt, kw in formats:
        p = tmp_path / name
        if fmt in ("obj", "off", "stl"):
            if name == "b.stl" and np.isfinite(value):
                continue  # single precision holds none of these: inf, 0; nan and inf are tested
            surface = meshio.Mesh(pts, [("triangle", np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))])
            meshio.write(p, surface, file_format=fmt, **kw)
            cmd = [exe, "tetrahedralize", str(p)]
        else:
            meshio.write(p, mesh, file_format=fmt, **kw)
            cmd = [exe, "check", str(p)]
        out = subprocess.run(cmd, capture_output=True, text=True)
        assert out.returncode == 2, (name, value, out.stdout, out.stderr)
        assert p.stem in out.stderr and out.stderr.count("\n") == 1, (name, out.stderr)
        assert ("exactly supported" in out.stderr or "not a number" in out.stderr
                or "below the" in out.stderr), (name, out.stderr)
